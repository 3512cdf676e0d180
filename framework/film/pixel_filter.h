// Pixel filters: the four 1D profiles stage 1 writes (assignments/stage1), scaled to a chosen
// support and combined into a separable 2D filter. Stage 1 hands its profiles (and its splat) on
// through the stage kit (render/stage_kit.h); the film only sees them through PixelFilter.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "film/film.h"

namespace pathway {

enum class FilterType { Box, Tent, MitchellNetravali, Gaussian };

// The widest support a filter may be given, in pixels (it must fit the renderer's tile margins).
constexpr float kMaxFilterRadius = 8.0f;

// "box", "tent", "mitchell", "gaussian"; throws PathwayError naming the valid choices otherwise.
FilterType parseFilterType(const std::string& name);
std::string filterTypeName(FilterType type);
std::vector<std::string> filterTypeNames();
// The support radius each profile is written for: box 0.5, tent 1, Mitchell-Netravali 2,
// Gaussian 1.5 (σ = 0.5, cut at 3σ).
float naturalFilterRadius(FilterType type);
// Whether the filter has negative lobes (Mitchell-Netravali): only then can non-negative radiance
// make a negative pixel.
inline bool hasNegativeLobes(FilterType type) {
  return type == FilterType::MitchellNetravali;
}

// The 1D profiles, centred on 0, on their natural support (stage 1 writes them).
struct FilterProfiles {
  float (*box)(float x) = nullptr;
  float (*tent)(float x) = nullptr;
  float (*mitchellNetravali)(float x) = nullptr;
  float (*gaussian)(float x, float sigma) = nullptr;  // cut to 0 beyond 3σ
};

// A 2D separable filter f(dx, dy) = f(dx)·f(dy), scaled to a chosen support radius.
class PixelFilter {
 public:
  PixelFilter(FilterType type, float radius, const FilterProfiles& profiles);

  float radius() const { return radius_; }  // f is 0 when |dx| or |dy| exceeds it
  float evaluate1D(float d) const;
  float evaluate(float dx, float dy) const { return evaluate1D(dx) * evaluate1D(dy); }

 private:
  FilterType type_;
  float radius_;
  float scale_;  // natural radius / chosen radius: stretches the profile to the chosen support
  FilterProfiles profiles_;
};

}  // namespace pathway
