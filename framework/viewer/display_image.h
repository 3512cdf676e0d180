// What the viewer shows of a lane's frame, as 8-bit RGBA for a texture: the colour image
// (exposure, sRGB), the per-pixel variance of the estimate, or the rays traced per camera sample.
// The last two are false-coloured and scaled to their own range, which is returned for the legend
// (rays on a log scale: falseColorPosition).
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

// `exposure` in stops, for the colour mode. The false-colour modes scale to `scaleMax` when it is
// above 0 (one scale shared by the panes of a split view), else to the frame's own range.
DisplayImage makeDisplayImage(const LaneFrame& frame, DisplayMode mode, float exposure,
                              float scaleMax = 0.0f);

// The top of a false-colour mode's scale for this frame alone (0 for colour, or nothing to show).
float displayScaleTop(const LaneFrame& frame, DisplayMode mode);

// One scale for panes shown side by side: the larger of their own tops, so the noisier pane fills
// the scale and the other shows how much less noise it has (two own scales would make both look
// alike). Null frames are skipped.
float sharedScaleTop(const LaneFrame* const* frames, int count, DisplayMode mode);

// Any linear RGB image (e.g. the grader's heatmap), sRGB-encoded, opaque.
DisplayImage displayImageOf(const Image& image);

// Where `value` sits on a false-colour scale topping out at `top`, in [0, 1] (clamped by
// falseColor): linear for the variance; logarithmic from 1 for rays per camera sample, which
// multiply with every bounce of naive recursion, so that each ×N is one equal step.
float falseColorPosition(DisplayMode mode, float value, float top);

// The false-colour scale (viridis) at t in [0, 1], as 8-bit RGB.
void falseColor(float t, uint8_t rgb[3]);

}  // namespace pathway
