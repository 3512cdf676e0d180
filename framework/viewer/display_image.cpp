#include "viewer/display_image.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "io/image_io.h"

namespace pathway {
namespace {

// linearToSrgb() for every 8-bit output would cost a pow() per channel per frame; a table over
// [0, 1] is exact to well under one 8-bit step.
const std::array<uint8_t, 4096>& srgbTable() {
  static const std::array<uint8_t, 4096> table = [] {
    std::array<uint8_t, 4096> t{};
    for (size_t i = 0; i < t.size(); ++i)
      t[i] = static_cast<uint8_t>(
          std::lround(255.0f * linearToSrgb(static_cast<float>(i) / (t.size() - 1))));
    return t;
  }();
  return table;
}

uint8_t encode(float linear) {
  if (!(linear > 0.0f)) return 0;  // also catches NaN
  if (linear >= 1.0f) return 255;
  return srgbTable()[static_cast<size_t>(linear * 4095.0f + 0.5f)];
}

// The top of the colour scale: the 99th percentile, so one firefly (or, in the ray heatmap, a
// sample counted in its neighbour pixel after float rounding) does not turn the rest dark.
float scaleTop(std::vector<float> values) {
  values.erase(std::remove_if(values.begin(), values.end(),
                              [](float v) { return !std::isfinite(v) || v <= 0.0f; }),
               values.end());
  if (values.empty()) return 0.0f;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(0.99 * values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}

void falseColorImage(DisplayImage& out, const std::vector<float>& values, DisplayMode mode,
                     float scaleMax) {
  out.scaleMax = scaleMax > 0.0f ? scaleMax : scaleTop(values);
  for (size_t i = 0; i < values.size(); ++i) {
    falseColor(falseColorPosition(mode, values[i], out.scaleMax), &out.rgba[4 * i]);
    out.rgba[4 * i + 3] = 255;
  }
}

// The values a false-colour mode shows, per pixel; empty when the frame has none.
std::vector<float> falseColorValues(const LaneFrame& frame, DisplayMode mode) {
  const size_t count = frame.images.color.pixels.size();
  std::vector<float> values;
  if (mode == DisplayMode::Variance && frame.images.variance.pixels.size() == count) {
    values.resize(count);
    for (size_t i = 0; i < count; ++i) {
      const Color& v = frame.images.variance.pixels[i];
      values[i] = (v.x + v.y + v.z) / 3.0f;
    }
  } else if (mode == DisplayMode::RayHeatmap && frame.raysPerSample.size() == count) {
    values = frame.raysPerSample;
  }
  return values;
}

}  // namespace

float falseColorPosition(DisplayMode mode, float value, float top) {
  if (!std::isfinite(value)) return 1.0f;
  if (mode == DisplayMode::RayHeatmap)
    return value > 1.0f && top > 1.0f ? std::log(value) / std::log(top) : 0.0f;
  return top > 0.0f ? value / top : 0.0f;
}

void falseColor(float t, uint8_t rgb[3]) {
  // Viridis at nine evenly spaced stops, linearly interpolated.
  static const float stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},
                                    {44, 113, 142}, {33, 144, 141}, {39, 173, 129},
                                    {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  const float x = std::clamp(t, 0.0f, 1.0f) * 8.0f;
  const int i = std::min(static_cast<int>(x), 7);
  const float f = x - static_cast<float>(i);
  for (int c = 0; c < 3; ++c)
    rgb[c] = static_cast<uint8_t>(stops[i][c] + f * (stops[i + 1][c] - stops[i][c]) + 0.5f);
}

DisplayImage displayImageOf(const Image& image) {
  DisplayImage out;
  out.width = image.width;
  out.height = image.height;
  out.rgba.assign(4 * image.pixels.size(), 255);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) out.rgba[4 * i + c] = encode(image.pixels[i][c]);
  return out;
}

DisplayImage makeDisplayImage(const LaneFrame& frame, DisplayMode mode, float exposure,
                              float scaleMax) {
  DisplayImage out;
  const Image& color = frame.images.color;
  out.width = color.width;
  out.height = color.height;
  const size_t count = static_cast<size_t>(out.width) * out.height;
  out.rgba.assign(4 * count, 255);
  if (count == 0) return out;

  if (mode == DisplayMode::Color) {
    const float scale = std::exp2(exposure);
    for (size_t i = 0; i < count; ++i)
      for (int c = 0; c < 3; ++c) out.rgba[4 * i + c] = encode(color.pixels[i][c] * scale);
  } else {
    const std::vector<float> values = falseColorValues(frame, mode);
    if (values.size() == count) falseColorImage(out, values, mode, scaleMax);
  }
  return out;
}

float displayScaleTop(const LaneFrame& frame, DisplayMode mode) {
  if (mode == DisplayMode::Color) return 0.0f;
  return scaleTop(falseColorValues(frame, mode));
}

float sharedScaleTop(const LaneFrame* const* frames, int count, DisplayMode mode) {
  float top = 0.0f;
  for (int i = 0; i < count; ++i)
    if (frames[i]) top = std::max(top, displayScaleTop(*frames[i], mode));
  return top;
}

}  // namespace pathway
