#include "grade/jackknife_render.h"

#include <utility>

namespace pathway {

uint32_t sampleBatchCount(uint32_t spp) {
  for (uint32_t count = kMostSampleBatches; count > 1; --count)
    if (spp % count == 0) return count;
  return 1;
}

RenderResult renderWithJackknife(const RayTracer& tracer, const RenderRecipe& recipe,
                                 bool jackknife) {
  if (!jackknife) return runRender(tracer, recipe);
  const uint32_t samples = recipe.settings.samplesToRender();
  const uint32_t batches = sampleBatchCount(samples);
  RenderRecipe inBatches = recipe;
  inBatches.settings.samplesPerPass = samples / batches;  // one pass per batch
  const Camera camera(tracer.scene(), recipe.settings.width, recipe.settings.height);
  RenderSession session(tracer, camera, inBatches);
  std::vector<Film> batchSums;
  Film before(recipe.settings.width, recipe.settings.height);
  while (!session.renderer().finished()) {
    session.renderer().renderPass();
    Film now = session.renderer().film();
    batchSums.emplace_back(now) -= before;
    before = std::move(now);
  }
  RenderResult result = session.develop();
  if (batchSums.size() < 2) return result;
  for (const Film& batch : batchSums) {
    Film without = session.renderer().film();
    without -= batch;
    result.images.jackknife.push_back(without.develop());
  }
  return result;
}

}  // namespace pathway
