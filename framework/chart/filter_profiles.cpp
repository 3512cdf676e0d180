#include "chart/filter_profiles.h"

#include <vector>

#include "core/error.h"
#include "core/number_format.h"
#include "film/pixel_filter.h"
#include "render/stage_kit.h"

namespace pathway {

std::string filterProfilesCsv(Variant* used) {
  const Stage1Functions* stage1 = nullptr;
  for (Variant variant : {Variant::Reference, Variant::Student}) {
    try {
      stage1 = &StageKit(1, variant, EarlierStages::Own).stage1();
      *used = variant;
      break;
    } catch (const PathwayError&) {
      // not built into this program: try the next
    }
  }
  if (!stage1) throw PathwayError("no stage 1 is built into this program");
  const FilterType types[] = {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali,
                              FilterType::Gaussian};
  std::vector<PixelFilter> filters;
  std::string csv = "x";
  for (FilterType type : types) {
    filters.emplace_back(type, naturalFilterRadius(type), stage1->profiles);
    csv += "," + filterTypeName(type);
  }
  csv += "\n";
  constexpr int kSteps = 1000;  // fine enough to show the box's jump as a vertical edge
  for (int i = 0; i <= kSteps; ++i) {
    const float x = -2.5f + 5.0f * float(i) / kSteps;
    csv += formatNumber("%.4f", x);
    for (const PixelFilter& filter : filters) csv += formatNumber(",%.7g", filter.evaluate1D(x));
    csv += "\n";
  }
  return csv;
}

}  // namespace pathway
