#include "film/pixel_filter.h"

#include <cmath>

#include "core/error.h"

namespace pathway {
namespace {

const FilterType kFilterTypes[] = {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali,
                                   FilterType::Gaussian};

}  // namespace

std::string filterTypeName(FilterType type) {
  switch (type) {
    case FilterType::Box:
      return "box";
    case FilterType::Tent:
      return "tent";
    case FilterType::MitchellNetravali:
      return "mitchell";
    case FilterType::Gaussian:
      return "gaussian";
  }
  return "?";
}

std::vector<std::string> filterTypeNames() {
  std::vector<std::string> names;
  for (FilterType type : kFilterTypes) names.push_back(filterTypeName(type));
  return names;
}

FilterType parseFilterType(const std::string& name) {
  for (FilterType type : kFilterTypes)
    if (filterTypeName(type) == name) return type;
  throw PathwayError("unknown filter '" + name + "' (choose box, tent, mitchell or gaussian)");
}

float naturalFilterRadius(FilterType type) {
  switch (type) {
    case FilterType::Box:
      return 0.5f;
    case FilterType::Tent:
      return 1.0f;
    case FilterType::MitchellNetravali:
      return 2.0f;
    case FilterType::Gaussian:
      return 1.5f;
  }
  return 1.0f;
}

PixelFilter::PixelFilter(FilterType type, float radius, const FilterProfiles& profiles)
    : type_(type), radius_(radius), profiles_(profiles) {
  if (!(radius > 0.0f) || !std::isfinite(radius) || radius > kMaxFilterRadius)
    throw PathwayError("filter radius must be in (0, " + std::to_string(kMaxFilterRadius) +
                       "] pixels, got " + std::to_string(radius));
  scale_ = naturalFilterRadius(type) / radius;
}

float PixelFilter::evaluate1D(float d) const {
  if (std::fabs(d) > radius_) return 0.0f;
  const float x = d * scale_;
  switch (type_) {
    case FilterType::Box:
      return profiles_.box(x);
    case FilterType::Tent:
      return profiles_.tent(x);
    case FilterType::MitchellNetravali:
      return profiles_.mitchellNetravali(x);
    case FilterType::Gaussian:
      return profiles_.gaussian(x, naturalFilterRadius(type_) / 3.0f);
  }
  return 0.0f;
}

}  // namespace pathway
