#include "grade/jackknife_render.h"

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
    Film& batch = batchSums.emplace_back(session.renderer().film());
    batch -= before;
    before = session.renderer().film();
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

glm::dvec3 jackknifeVariance(const std::vector<Image>& jackknife, int x0, int y0, int x1, int y1) {
  std::vector<glm::dvec3> means;
  glm::dvec3 sum(0.0);
  for (const Image& image : jackknife) {
    glm::dvec3 pixels(0.0);
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) pixels += glm::dvec3(image.at(x, y));
    sum += means.emplace_back(pixels / (double(x1 - x0) * (y1 - y0)));
  }
  const double count = static_cast<double>(jackknife.size());
  const glm::dvec3 average = sum / count;
  glm::dvec3 squares(0.0);
  for (const glm::dvec3& m : means) squares += (m - average) * (m - average);
  return squares * (count - 1.0) / count;
}

}  // namespace pathway
