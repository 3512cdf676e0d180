// The pixel filters' 1D profiles as the code evaluates them (stage 1's filter functions, through
// PixelFilter at each filter's natural radius), tabulated for plotting: the chart of the filters
// shows what the renderer really splats with, not a textbook curve.
#pragma once

#include <string>

#include "core/variant.h"

namespace pathway {

// CSV "x,box,tent,mitchell,gaussian" for x from -2.5 to 2.5 pixels. Uses the reference's stage 1
// when it is built in, else the student's; `used` tells which.
std::string filterProfilesCsv(Variant* used);

}  // namespace pathway
