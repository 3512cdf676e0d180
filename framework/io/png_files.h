// Writing PNG files through libpng itself. Renders, charts, grading reports and viewer screenshots
// all write PNGs; going through OpenImageIO for them cost every such command about a quarter of a
// second of loading its libraries. Reading PNGs stays with the image-file module (raster.h).
#pragma once

#include <cstdint>
#include <string>

#include "io/raster.h"

namespace pathway {

// 8-bit pixels, channel-interleaved, rows top to bottom; 1 (grey), 2 (grey, alpha), 3 (RGB) or
// 4 (RGBA) channels, taken as sRGB-encoded. Throws PathwayError naming `path` and the reason.
void writePngRaster(const std::string& path, const RasterHeader& header, const uint8_t* pixels);

}  // namespace pathway
