#include "grade/grade_calibration.h"

#include <algorithm>
#include <chrono>
#include <map>

#include "grade/grading_reference.h"
#include "grade/jackknife_render.h"
#include "grade/reference_comparison.h"
#include "grade/stage_grading.h"
#include "scene/gltf_loader.h"

namespace pathway {

CalibrationResult calibrate(const GradingCase& gradingCase, uint32_t spp, Variant variant,
                            ReferenceTracing tracing, int seeds, uint64_t firstSeed,
                            const std::string& referencesFolder, const std::string& scenesFolder,
                            const ComparisonSettings& settings,
                            const std::function<void(int)>& onSeed) {
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
  for (int i = 0; i < seeds; ++i) {
    Comparison comparison, confirmation;
    const bool passed = passes(firstSeed + i, &comparison);
    if (comparison.closeness >= 0 &&
        (result.smallestCloseness < 0 || comparison.closeness < result.smallestCloseness)) {
      result.smallestCloseness = comparison.closeness;
      result.smallestClosenessP = comparison.closenessP;
    }
    if (i == 0 || comparison.noiseRatio < result.smallestNoiseRatio)
      result.smallestNoiseRatio = comparison.noiseRatio;
    result.largestNoiseRatio = std::max(result.largestNoiseRatio, comparison.noiseRatio);
    result.tooNoisy += comparison.tooNoisy();
    if (!passed) {
      // As the grader does: a failure counts when a render with another seed fails too.
      if (!passes(firstSeed + i + kConfirmationSeedOffset, &confirmation))
        result.verdictSeeds.push_back(firstSeed + i);
      ++result.failures;
      result.failedSeeds.push_back(firstSeed + i);
      result.largestWorstP =
          std::max(result.largestWorstP, std::min(comparison.worstTileP, comparison.omnibusP));
    }
    if (onSeed) onSeed(i + 1);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace pathway
