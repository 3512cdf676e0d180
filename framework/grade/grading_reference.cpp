#include "grade/grading_reference.h"

#include <algorithm>

#include "core/error.h"
#include "grade/difference_diagnosis.h"
#include "grade/difference_patterns.h"
#include "grade/jackknife_render.h"
#include "io/image_io.h"

namespace pathway {
GradingReference makeGradingReference(const GradingCase& gradingCase, const RayTracer& tracer,
                                      ReferenceTracing tracing) {
  std::vector<Image> replicates;
  Image ownVariance;  // the mean of the replicates' own per-pixel variance estimates
  GradingReference reference;
  const int blockSize = ComparisonSettings().omnibusBlockSize;
  std::vector<Image>
      ownJackknives;  // each replicate's jackknifeBlockVariance, for its typical noise
  double seconds = 0.0, rays = 0.0;
  for (int i = 0; i < kReferenceReplicates; ++i) {
    const RenderRecipe recipe =
        gradingCase.recipe(Variant::Reference, EarlierStages::Own, kReferenceSeed + i, tracing);
    // In batches where a submission's own noise counts: the jackknife is estimated as for theirs.
    RenderResult result = renderWithJackknife(tracer, recipe, gradingCase.ownNoiseCounts());
    if (result.stats.counters.invalidSamples > 0)
      throw PathwayError(gradingCase.id() + ": the reference dropped " +
                         std::to_string(result.stats.counters.invalidSamples) +
                         " non-finite samples; this case cannot be graded");
    if (i == 0) reference.metadata = result.metadata;
    seconds += result.stats.seconds;
    rays += static_cast<double>(result.stats.counters.totalRays());
    if (ownVariance.pixels.empty())
      ownVariance = Image(result.images.variance.width, result.images.variance.height);
    for (size_t p = 0; p < ownVariance.pixels.size(); ++p)
      ownVariance.pixels[p] += result.images.variance.pixels[p] / float(kReferenceReplicates);
    if (!result.images.jackknife.empty()) {
      const Image own = jackknifeBlockVariance(result.images.jackknife, blockSize);
      if (reference.jackknifeVariance.pixels.empty())
        reference.jackknifeVariance = Image(own.width, own.height);
      for (size_t p = 0; p < own.pixels.size(); ++p)
        reference.jackknifeVariance.pixels[p] += own.pixels[p] / float(kReferenceReplicates);
      ownJackknives.push_back(own);
    }
    replicates.push_back(std::move(result.images.color));
  }
  reference.mean = Image(replicates.front().width, replicates.front().height);
  for (size_t p = 0; p < reference.mean.pixels.size(); ++p) {
    glm::dvec3 sum(0.0);
    for (const Image& replicate : replicates) sum += glm::dvec3(replicate.pixels[p]);
    reference.mean.pixels[p] = Color(sum / double(replicates.size()));
  }
  reference.tileVariance = replicateTileVariance(replicates, gradingCase.tileSize);
  reference.patterns =
      makeDifferencePatterns(gradingCase, tracer, reference.mean, ownVariance, tracing);
  GradingRecord& record = reference.record;
  record.caseId = gradingCase.id();
  record.blockSize = blockSize;
  reference.blockVariance = replicateTileVariance(replicates, record.blockSize);
  record.blockCorrelation = replicateBlockCorrelation(replicates, record.blockSize);
  record.replicates = kReferenceReplicates;
  // A replicate's typical noise, the median over them: what a submission's is held against.
  std::vector<double> typical;
  for (const Image& own : ownJackknives)
    typical.push_back(typicalNoise(own, reference.jackknifeVariance, blockSize));
  if (!typical.empty()) {
    std::nth_element(typical.begin(), typical.begin() + typical.size() / 2, typical.end());
    record.typicalNoise = typical[typical.size() / 2];
  }
  record.tileSize = gradingCase.tileSize;
  record.secondsPerRender = seconds / kReferenceReplicates;
  record.raysPerSecond = seconds > 0.0 ? rays / seconds : 0.0;
  // Students get a multiple of this time and see these rays/s beside theirs: one ray at a time,
  // as their stage traces, even when the replicates came from the faster wavefront version.
  const RenderRecipe singleRay = gradingCase.recipe(Variant::Reference, EarlierStages::Own,
                                                    kReferenceSeed, ReferenceTracing::SingleRay);
  if (singleRay.integrator != reference.metadata.integrator) {
    const RenderResult timed = runRender(tracer, singleRay);
    record.secondsPerRender = timed.stats.seconds;
    record.raysPerSecond =
        timed.stats.seconds > 0.0 ? timed.stats.counters.totalRays() / timed.stats.seconds : 0.0;
  }
  // The replicates' own seed, timing and file path would only mislead (the scene is known by
  // its content hash): the reference's timing is in its record.
  reference.metadata.seed.reset();
  reference.metadata.timing.reset();
  reference.metadata.scene.clear();
  return reference;
}

void writeGradingReference(const std::string& path, const GradingReference& reference) {
  RenderMetadata metadata = reference.metadata;
  metadata.grading = reference.record;
  std::map<std::string, const Image*> layers = {{"", &reference.mean},
                                                {"tileVariance", &reference.tileVariance},
                                                {"blockVariance", &reference.blockVariance}};
  if (!reference.jackknifeVariance.pixels.empty())
    layers["jackknifeVariance"] = &reference.jackknifeVariance;
  for (const auto& [name, image] : reference.patterns) layers[name] = &image;
  writeExrLayers(path, layers, metadata);
}

GradingReference readGradingReference(const std::string& path) {
  return gradingReferenceOf(readImageFile(path), path);  // names the file when it is broken
}

GradingReference gradingReferenceOf(LoadedImage loaded, const std::string& path) {
  if (!loaded.metadata.grading)
    throw PathwayError(path + ": not a grading reference (no grading record in its metadata)");
  GradingReference reference;
  reference.record = *loaded.metadata.grading;
  const GradingRecord& record = reference.record;
  if (record.replicates < 2 || record.tileSize < 1 || record.blockSize < 1)
    throw PathwayError(path +
                       ": a grading reference needs at least 2 replicates and tiles of 1+ "
                       "pixels");
  for (const char* layer : {"tileVariance", "blockVariance"})
    if (!loaded.layers.count(layer))
      throw PathwayError(path + ": not a grading reference (no " + layer + " layer)");
  reference.mean = std::move(loaded.images.color);
  reference.tileVariance = std::move(loaded.layers["tileVariance"]);
  reference.blockVariance = std::move(loaded.layers["blockVariance"]);
  if (auto jackknife = loaded.layers.find("jackknifeVariance"); jackknife != loaded.layers.end())
    reference.jackknifeVariance = std::move(jackknife->second);
  for (auto& [name, image] : loaded.layers)
    if (name.rfind(pattern::kPrefix, 0) == 0) reference.patterns[name] = std::move(image);
  reference.metadata = std::move(loaded.metadata);
  reference.metadata.grading.reset();
  return reference;
}

}  // namespace pathway
