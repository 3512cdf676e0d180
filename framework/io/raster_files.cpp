#include "io/raster_files.h"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <mutex>

#include "core/error.h"
#include "io/exr_files.h"
#include "io/png_files.h"

namespace pathway {
namespace {

struct ImageFileModule {
  WriteRasterFunction write = nullptr;
  ReadRasterFunction read = nullptr;
  std::string error;  // why it could not be loaded
};

// Loaded once, by the first thread that needs it; never unloaded (OpenImageIO keeps threads).
const ImageFileModule& imageFileModule() {
  static ImageFileModule module;
  static std::once_flag loaded;
  std::call_once(loaded, [] {
    void* handle = dlopen(PATHWAY_IMAGE_FILE_MODULE, RTLD_NOW | RTLD_LOCAL);
    if (!handle) {
      module.error = std::string("cannot load the image-file module: ") + dlerror();
      return;
    }
    module.write = reinterpret_cast<WriteRasterFunction>(dlsym(handle, "pathwayWriteRaster"));
    module.read = reinterpret_cast<ReadRasterFunction>(dlsym(handle, "pathwayReadRaster"));
    if (!module.write || !module.read)
      module.error = "the image-file module " PATHWAY_IMAGE_FILE_MODULE " lacks its functions";
  });
  if (!module.error.empty()) throw PathwayError(module.error);
  return module;
}

}  // namespace

void writeRaster(const std::string& path, const RasterHeader& header, bool eightBit,
                 const void* pixels) {
  const std::string extension = lowerExtension(path);
  if (extension == ".exr" && !eightBit)
    return writeExrRaster(path, header, static_cast<const float*>(pixels));
  if (extension == ".png" && eightBit)
    return writePngRaster(path, header, static_cast<const uint8_t*>(pixels));
  std::string error;
  if (!imageFileModule().write(path.c_str(), header, eightBit, pixels, error))
    throw PathwayError(path + ": writing failed: " + error);
}

std::string lowerExtension(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return extension;
}

Raster readRaster(const std::string& path, const RasterLimits& limits) {
  if (lowerExtension(path) == ".exr") return readExrRaster(path, limits);
  if (limits.any()) throw PathwayError(path + ": cannot read image: not an EXR file");
  Raster raster;
  std::string error;
  if (!imageFileModule().read(path.c_str(), raster, error))
    throw PathwayError(path + ": cannot read image: " + error);
  return raster;
}

}  // namespace pathway
