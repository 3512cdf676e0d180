// What the viewer shows of a lane's frame, as 8-bit RGBA for a texture: the colour image
// (exposure, sRGB), the per-pixel variance of the estimate, or the rays traced per camera sample.
// The last two are false-coloured and scaled to their own range, which is returned for the legend.
#pragma once

#include <cstdint>
#include <vector>

#include "viewer/render_worker.h"

namespace pathway {

enum class DisplayMode { Color, Variance, RayHeatmap };

struct DisplayImage {
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // rows top to bottom
  float scaleMax = 0.0f;      // variance / rays per sample shown at the top of the colour scale
};

// `exposure` in stops, for the colour mode.
DisplayImage makeDisplayImage(const LaneFrame& frame, DisplayMode mode, float exposure);

// Any linear RGB image (e.g. the grader's heatmap), sRGB-encoded, opaque.
DisplayImage displayImageOf(const Image& image);

// The false-colour scale (viridis) at t in [0, 1], as 8-bit RGB.
void falseColor(float t, uint8_t rgb[3]);

}  // namespace pathway
