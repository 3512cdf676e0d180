// Reading and writing rasters: EXR through OpenEXR (exr_files.h), 8-bit PNG output through libpng
// (png_files.h), everything else (reading PNG too) through the image-file module (raster.h),
// loaded on first use.
#pragma once

#include <string>

#include "io/raster.h"

namespace pathway {

// Writes `pixels` (float, or 8-bit when `eightBit`) to `path` as its extension says. Throws
// PathwayError naming the path and the reason (also when the module cannot be loaded).
void writeRaster(const std::string& path, const RasterHeader& header, bool eightBit,
                 const void* pixels);
// Throws PathwayError naming the path and the reason. With `limits`, an EXR only (what the
// grader's children write), checked against them before its pixels are read.
Raster readRaster(const std::string& path, const RasterLimits& limits = {});

// The file's extension in lower case, with its dot (".exr"): it picks the format.
std::string lowerExtension(const std::string& path);

}  // namespace pathway
