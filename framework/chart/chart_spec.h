// What a convergence chart measures: a scene, an image size, the sample counts 2^0 ... 2^k, the
// seeds, and the configurations to compare (integrator, parameters, sampler, filter). Each setting
// is declared here once with its default and range; `pathway chart` reads them from here.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "engine/render_choices.h"
#include "engine/render_settings.h"

namespace pathway {

namespace setting {
// Charts render many small images: the render setting's width, smaller by default.
inline const OptionSpec kChartWidth =
    kWidth.withDefault(128, "Image width in pixels (height: from the camera)");
inline const OptionSpec kChartMaxSpp = OptionSpec::integer(
    "max-spp", 256, 1, 1 << 16, "Largest spp charted, a power of two: spp = 1, 2, 4 ... max-spp");
inline const OptionSpec kChartSeeds =
    OptionSpec::integer("seeds", 4, 1, 64, "Renders per point, each with its own seed");
// The reference's own error must be negligible next to the charted errors: at 64x the largest
// spp it adds about 1/64 to the relMSE of the best point (the two are independent).
inline const OptionSpec kReferenceFactor = OptionSpec::integer(
    "reference-factor", 64, 64, 4096, "Reference spp as a multiple of the largest charted spp");
}  // namespace setting

// One line on a chart.
struct ChartConfig {
  std::string label;      // as the legend shows it; unique within a chart
  RenderChoices choices;  // integrator, parameters, sampler, filter; choices.scene empty: chart's
  uint32_t maxSpp = 0;    // 0: the chart's --max-spp
  // The configuration whose recipe renders this one's reference (empty: its own). Only for
  // configurations that estimate the same image, e.g. path tracing with and without NEE.
  std::string referenceFrom;
  std::string group;        // sweep figures: which curve the point belongs to ("NEE on")
  std::optional<double> x;  // sweep figures: where it sits on the x axis (light size)
  std::string source;       // the text it was read from, for messages
};

// Reads "LABEL: INTEGRATOR [key=value ...]" (the label ends at the first ": "; a value with
// spaces goes in double quotes). Keys: sampler, filter, filter-radius, scene, max-spp, reference
// (a label), group, x; any other key is a parameter of the integrator.
// Throws PathwayError naming the text and what is wrong (the integrator and its parameters are
// checked later, by ChartSpec::check).
ChartConfig parseChartConfig(const std::string& text);

struct ChartSpec {
  std::string title;  // over the chart
  std::string scene;  // for configurations without scene=
  int width = setting::kChartWidth.defaultAs<int>();
  uint32_t maxSpp = setting::kChartMaxSpp.defaultAs<uint32_t>();
  int seeds = setting::kChartSeeds.defaultAs<int>();
  uint32_t referenceFactor = setting::kReferenceFactor.defaultAs<uint32_t>();
  bool withReference = true;  // false: time and rays only, no errors (ray-count charts)
  std::vector<ChartConfig> configs;

  // Every configuration's recipe checked (integrator, parameters, values in range), labels unique,
  // spp powers of two, references naming a configuration of the same scene and filter. Throws
  // PathwayError naming the configuration and the problem.
  void check() const;
  uint32_t maxSppOf(const ChartConfig& config) const;
  const std::string& sceneOf(const ChartConfig& config) const;
  const ChartConfig& referenceConfigOf(const ChartConfig& config) const;
};

bool isPowerOfTwo(uint32_t value);

}  // namespace pathway
