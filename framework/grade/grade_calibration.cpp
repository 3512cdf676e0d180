#include "grade/grade_calibration.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <vector>

#include "grade/grading_reference.h"
#include "grade/jackknife_render.h"
#include "grade/reference_comparison.h"
#include "grade/stage_grading.h"
#include "scene/gltf_loader.h"

namespace pathway {

CalibrationResult calibrate(const GradingCase& gradingCase, uint32_t spp, Variant variant,
                            ReferenceTracing tracing, int seeds, uint64_t firstSeed,
                            const std::string& referencesFolder, const std::string& scenesFolder,
                            const ComparisonSettings& settings) {
  GradingCase atSpp = gradingCase;
  atSpp.spp = spp;
  const Scene scene = loadScene(scenesFolder + "/" + gradingCase.scene);
  const RayTracer tracer(scene);
  const GradingReference reference =
      spp == gradingCase.spp
          ? readGradingReference(referencesFolder + "/" + gradingCase.referenceFile())
          : makeGradingReference(atSpp, tracer, tracing);

  CalibrationResult result;
  result.caseId = gradingCase.id();
  result.spp = spp;
  result.seeds = seeds;
  const auto start = std::chrono::steady_clock::now();
  auto passes = [&](uint64_t seed, Comparison* comparison) {
    const RenderRecipe recipe = atSpp.recipe(variant, EarlierStages::Reference, seed, tracing);
    const RenderResult render = renderWithJackknife(tracer, recipe, gradingCase.ownNoiseCounts());
    *comparison = compareWithReference(render.images, render.metadata, reference, settings);
    return comparison->passed(settings);
  };
  // What the table needs of one seed's grading (a Comparison holds every tile's verdict).
  struct SeedOutcome {
    bool passed = true, confirmed = false;  // confirmed: the confirmation render failed too
    double closeness, closenessP, noiseRatio, worstP;
    bool tooNoisy;
  };
  // The seeds are graded side by side: small images leave cores idle within one render. Each
  // seed's render is the same whoever runs it, and the outcomes are gathered in seed order.
  std::vector<SeedOutcome> outcomes(static_cast<size_t>(std::max(seeds, 0)));
  tbb::parallel_for(0, seeds, [&](int i) {
    Comparison comparison, confirmation;
    SeedOutcome& o = outcomes[static_cast<size_t>(i)];
    o.passed = passes(firstSeed + i, &comparison);
    // As the grader does: a failure counts when a render with another seed fails too.
    if (!o.passed) o.confirmed = !passes(firstSeed + i + kConfirmationSeedOffset, &confirmation);
    o.closeness = comparison.closeness;
    o.closenessP = comparison.closenessP;
    o.noiseRatio = comparison.noiseRatio;
    o.worstP = std::min(comparison.worstTileP, comparison.omnibusP);
    o.tooNoisy = comparison.tooNoisy();
  });
  for (int i = 0; i < seeds; ++i) {
    const SeedOutcome& o = outcomes[static_cast<size_t>(i)];
    if (o.closeness >= 0 &&
        (result.smallestCloseness < 0 || o.closeness < result.smallestCloseness)) {
      result.smallestCloseness = o.closeness;
      result.smallestClosenessP = o.closenessP;
    }
    if (i == 0 || o.noiseRatio < result.smallestNoiseRatio)
      result.smallestNoiseRatio = o.noiseRatio;
    result.largestNoiseRatio = std::max(result.largestNoiseRatio, o.noiseRatio);
    result.tooNoisy += o.tooNoisy;
    if (!o.passed) {
      if (o.confirmed) result.verdictSeeds.push_back(firstSeed + i);
      ++result.failures;
      result.failedSeeds.push_back(firstSeed + i);
      result.largestWorstP = std::max(result.largestWorstP, o.worstP);
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace pathway
