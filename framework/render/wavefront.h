// Wavefront integrators: many camera samples at a time, their rays traced together in Embree's
// 16-ray packets, each bounce of all the batch's paths at once. They are for the renders that
// are not student code (references, calibration, charts, cluster renders): a student's stage
// traces one ray at a time (render/integrator.h).
//
// A wavefront integrator computes the same estimator as its stage's reference, sample by sample:
// the same numbers from each sample's SampleStream in the same order, the same arithmetic. The
// renderer hands it the samples of a tile in the order it would have called Li, and splats the
// results in that order, so the image is still bit-identical for any thread count.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "render/stage_definition.h"

namespace pathway {

// One batch of camera samples: inputs (camera ray, the sample's numbers after the pixel
// position) and outputs (radiance, rays traced), index by index.
struct CameraSampleBatch {
  std::vector<Ray> cameraRays;
  std::vector<SampleStream> samples;
  std::vector<Color> radiance;
  std::vector<uint32_t> rays;  // rays each sample traced, for the ray heatmap

  size_t size() const { return cameraRays.size(); }
  void clear() {
    cameraRays.clear();
    samples.clear();
    radiance.clear();
    rays.clear();
  }
  void add(const Ray& cameraRay, const SampleStream& stream) {
    cameraRays.push_back(cameraRay);
    samples.push_back(stream);
  }
};

class WavefrontIntegrator : public Integrator {
 public:
  // How many samples the renderer gathers per call: enough that packets stay full after many
  // paths have ended.
  static constexpr size_t kBatchSize = 1024;
  virtual size_t batchSize() const { return kBatchSize; }

  // Fills batch.radiance and batch.rays, one per sample: for each, what Li would return.
  virtual void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const = 0;

  const WavefrontIntegrator* asWavefront() const final { return this; }

  // One sample: a batch of one.
  Color Li(const Ray& cameraRay, SampleStream& samples, const RenderContext& context) const final {
    CameraSampleBatch batch;
    batch.add(cameraRay, samples);
    LiBatch(batch, context);
    samples = batch.samples[0];
    return batch.radiance[0];
  }
};

// Traces rays[i] for every i in `which` (indices into `rays`) in packets of
// RayTracer::kPacketSize, and stores the answers at hits[i] / blocked[i]. Inline: a handout's
// compiled reference stages find the framework's functions in the program, which links only the
// framework code it uses itself (RayTracer's packet queries come with the rest of RayTracer).
inline void intersectAll(const RenderContext& context, const std::vector<Ray>& rays,
                         const std::vector<uint32_t>& which, RayKind kind,
                         std::vector<std::optional<SurfaceHit>>& hits) {
  for (size_t start = 0; start < which.size(); start += RayTracer::kPacketSize)
    context.tracer().intersectPacket(
        rays.data(), &which[start],
        static_cast<int>(std::min<size_t>(RayTracer::kPacketSize, which.size() - start)), kind,
        context.counters(), hits.data());
}

inline void occludedAll(const RenderContext& context, const std::vector<Ray>& rays,
                        const std::vector<uint32_t>& which, RayKind kind,
                        std::vector<uint8_t>& blocked) {
  for (size_t start = 0; start < which.size(); start += RayTracer::kPacketSize)
    context.tracer().occludedPacket(
        rays.data(), &which[start],
        static_cast<int>(std::min<size_t>(RayTracer::kPacketSize, which.size() - start)), kind,
        context.counters(), blocked.data());
}

// Registers `IntegratorType`, built from a StageSetup<Params> like the stage's reference, as the
// stage's wavefront version "stageN@fast" (in solutions/ only: it holds the stage's solution).
// Only where the file is built as the reference: a library built from a solution file as a
// student's (the grader's planted bugs) must not put its own wave in the reference's place.
// In an unnamed namespace, like registerStage, because its body depends on that build.
namespace {
template <typename IntegratorType, typename Params>
bool registerWavefrontStage(const StageDefinition<Params>& stage) {
#if defined(PATHWAY_VARIANT_REFERENCE)
  return registerWavefrontStageIntegrator(
      stage.info(), [&stage](const IntegratorSetup& setup) -> std::unique_ptr<Integrator> {
        const Params params = stage.read(setup.params);
        return std::make_unique<IntegratorType>(StageSetup<Params>{params, setup.kit, setup.scene});
      });
#else
  (void)stage;
  return false;
#endif
}
}  // namespace

}  // namespace pathway
