#include "io/png_files.h"

#include <png.h>

#include "core/error.h"

namespace pathway {

void writePngRaster(const std::string& path, const RasterHeader& header, const uint8_t* pixels) {
  // libpng's simplified API: it reports errors through `image.message` instead of longjmp, which
  // would skip C++ destructors.
  static constexpr png_uint_32 kFormats[] = {PNG_FORMAT_GRAY, PNG_FORMAT_GA, PNG_FORMAT_RGB,
                                             PNG_FORMAT_RGBA};
  const size_t channels = header.channels.size();
  if (channels < 1 || channels > 4)
    throw PathwayError(path + ": a PNG holds 1 to 4 channels, not " + std::to_string(channels));
  if (header.width <= 0 || header.height <= 0)
    throw PathwayError(path + ": cannot write an empty image");
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  image.width = static_cast<png_uint_32>(header.width);
  image.height = static_cast<png_uint_32>(header.height);
  image.format = kFormats[channels - 1];
  if (!png_image_write_to_file(&image, path.c_str(), 0, pixels, 0, nullptr))
    throw PathwayError(path + ": writing failed: " + image.message);
}

}  // namespace pathway
