// Image files as plain rasters. EXR goes through OpenEXR (exr_files.h) and PNG output through
// libpng (png_files.h); every other format, and reading PNG, through the image-file module
// (image_file_module.cpp, the one part of Pathway linked with OpenImageIO). OpenImageIO pulls in
// some 250 shared libraries, whose loading took a quarter of a second, so the module is loaded
// only when such a file is first read or written (raster_files.h).
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace pathway {

struct RasterHeader {
  int width = 0;
  int height = 0;
  std::vector<std::string> channels;                            // "R", "G", "B", "variance.R" ...
  std::vector<std::pair<std::string, std::string>> attributes;  // string metadata
  // EXR only: ZIP-compressed scanlines. Worth it for converged images such as grading references
  // (a quarter of the bytes), not for noisy renders, which shrink by a fifth in 18 times the time.
  bool compressed = false;
};

// What a reader expects of a file it does not trust (an image a grader's child wrote): its size,
// and at most so many channels. Checked against the file's header before any pixel memory is
// taken; 0 where nothing is expected.
struct RasterLimits {
  int width = 0;
  int height = 0;
  size_t maxChannels = 0;
  bool any() const { return width > 0 || height > 0 || maxChannels > 0; }
};

struct Raster {
  RasterHeader header;
  std::vector<float> pixels;  // channel-interleaved, rows top to bottom
};

// The module's two entry points (both built by this project with the same compiler, so C++
// types may cross). They return false and set `error` instead of throwing.
using WriteRasterFunction = bool (*)(const char* path, const RasterHeader& header, bool eightBit,
                                     const void* pixels, std::string& error);
using ReadRasterFunction = bool (*)(const char* path, Raster& raster, std::string& error);

}  // namespace pathway
