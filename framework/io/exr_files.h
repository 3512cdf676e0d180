// EXR files through OpenEXR itself: a handful of small shared libraries, loaded with the program
// in a few milliseconds, where OpenImageIO's ~250 took a quarter of a second. Every tool reads and
// writes EXR (renders, references, charts, grading), so this is the path that must be cheap.
#pragma once

#include <string>

#include "io/raster.h"

namespace pathway {

// Float channels, scanlines compressed as `header.compressed` says, string attributes. Throws
// PathwayError naming `path`.
void writeExrRaster(const std::string& path, const RasterHeader& header, const float* pixels);
// Every float or half channel as float (unsigned ones are skipped); R, G, B first when present (EXR
// stores channels sorted by name), then the others in the file's order; every string attribute.
// Throws PathwayError naming `path`, also when the file is larger, or its header declares another
// size or more channels, than `limits` allow.
Raster readExrRaster(const std::string& path, const RasterLimits& limits = {});

}  // namespace pathway
