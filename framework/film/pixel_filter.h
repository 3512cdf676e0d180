// Pixel filters and the splat: the contract between the framework and stage 1.
//
// Stage 1 (assignments/stage1) writes the four 1D filter profiles and the splat; it hands them to
// the framework as a FilterFunctions table, one table per variant (the student's and, when
// solutions/ is present, the reference). The renderer calls them through PixelFilter.
#pragma once

#include <string>
#include <vector>

#include "core/math.h"
#include "core/variant.h"
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

class PixelFilter;

// What stage 1 provides. Profiles are 1D, centred on 0, on their natural support.
struct FilterFunctions {
  float (*box)(float x) = nullptr;
  float (*tent)(float x) = nullptr;
  float (*mitchellNetravali)(float x) = nullptr;
  float (*gaussian)(float x, float sigma) = nullptr;  // cut to 0 beyond 3σ
  // Adds f_j·L and f_j to every pixel j whose filter support holds the sample at `position`.
  void (*splat)(FilmBlock& film, Vec2 position, const Color& radiance,
                const PixelFilter& filter) = nullptr;
};

void registerFilterFunctions(Variant variant, const FilterFunctions& functions);
// The table of `variant`; throws PathwayError when that variant is not built in.
const FilterFunctions& filterFunctions(Variant variant);

// A 2D separable filter f(dx, dy) = f(dx)·f(dy), scaled to a chosen support radius.
class PixelFilter {
 public:
  PixelFilter(FilterType type, float radius, const FilterFunctions& functions);

  float radius() const { return radius_; }  // f is 0 when |dx| or |dy| exceeds it
  float evaluate1D(float d) const;
  float evaluate(float dx, float dy) const { return evaluate1D(dx) * evaluate1D(dy); }

 private:
  FilterType type_;
  float radius_;
  float scale_;  // natural radius / chosen radius: stretches the profile to the chosen support
  const FilterFunctions* functions_;
};

}  // namespace pathway
