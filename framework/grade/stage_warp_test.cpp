#include "grade/stage_warp_test.h"

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "grade/light_sampling_fit.h"
#include "render/stage_kit.h"

namespace pathway {

bool hasWarpTest(int stage) {
  return stage == 2 || stage == 5;
}

StageWarpTest runStageWarpTest(int stage, Variant variant, const Scene* lights, int samples,
                               uint64_t seed, bool keepDirections) {
  StageWarpTest outcome;
  if (stage == 2) {
    const StageKit kit(2, variant, EarlierStages::Own);
    const Stage2Functions& stage2 = kit.stage2();
    WarpTestSettings settings;
    settings.samples = samples;
    settings.seed = seed;
    if (!keepDirections) settings.keptDirections = 0;
    outcome.hemisphere =
        testHemisphereWarp({stage2.sampleCosineHemisphere, stage2.cosineHemispherePdf}, settings);
    outcome.passed = outcome.hemisphere.passed;
    outcome.p = outcome.hemisphere.p;
    outcome.verdict = outcome.hemisphere.verdict;
    return outcome;
  }
  if (stage != 5) throw PathwayError("stage " + std::to_string(stage) + " has no warp test");
  if (!lights)
    throw PathwayError("stage 5's warp test needs its scene, " + std::string(kWarpTestScene));
  const Stage5Functions& stage5 = stage5Functions(variant);
  const std::vector<EmissiveTriangle> emitters = collectEmissiveTriangles(*lights);
  outcome.passed = true;
  for (const auto& [weighting, name] :
       {std::pair{EmitterWeighting::Area, "area"}, std::pair{EmitterWeighting::Power, "power"}}) {
    const EmitterPicker picker(*lights, weighting);
    LightSamplingTestSettings settings;
    settings.samples = samples;
    settings.seed = seed;
    const LightSamplingTestResult r =
        testLightSampling(stage5.sampleLight, picker, emitters, settings);
    outcome.passed = outcome.passed && r.passed;
    outcome.p = std::min({outcome.p, r.pickP, r.pointP});
    outcome.verdict += (outcome.verdict.empty() ? "" : "\n") + std::string("light-pick ") + name +
                       ": " + r.verdict;
  }
  return outcome;
}

}  // namespace pathway
