// The warp test as a picture (SVG, for a browser, a report or a slide): the directions seen from
// above, the histogram the routine drew, the histogram its pdf predicts, and their difference.
// A wrong warp shows as a ring or a hole in the difference; a wrong pdf as a whole band.
#pragma once

#include <string>

#include "grade/warp_fit.h"

namespace pathway {

// The picture of `result` as an SVG document; `title` is its first line (what was tested).
std::string warpTestSvg(const WarpTestResult& result, const std::string& title);

// Writes warpTestSvg to `path` (through a temporary name: never a half-written file). Throws
// PathwayError naming `path` when it does not end in .svg or cannot be written.
void writeWarpTestSvg(const std::string& path, const WarpTestResult& result,
                      const std::string& title);

}  // namespace pathway
