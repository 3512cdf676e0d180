// Stage 2's wavefront version, "stage2@fast": nested AO (stage2_nested_ao.cpp) on a batch of
// samples at once, for the renders that are not student code. The batch's eye rays are traced in
// 16-ray Embree packets, then its M AO rays per hit, all together. Each sample draws the same
// numbers and sums the same estimates in the same order as stage2@ref, so the images agree
// wherever packets and single rays report the same hits (test: WavefrontStages.*).
#include "ao_wavefront.h"
#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage2.h"

namespace pathway {
namespace {

class WavefrontNestedAmbientOcclusion : public WavefrontIntegrator {
 public:
  explicit WavefrontNestedAmbientOcclusion(const StageSetup<Stage2Params>& setup)
      : aoRays_(setup.params.aoRays),
        aoDistance_(setup.params.aoDistance),
        stage2_(setup.kit.stage2()) {}

  // M estimates per sample: fewer samples per batch as M grows, so its AO rays stay in cache.
  size_t batchSize() const override {
    return std::max<size_t>(RayTracer::kPacketSize, kBatchSize / static_cast<size_t>(aoRays_));
  }

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size(), m = static_cast<size_t>(aoRays_);
    thread_local Scratch s;
    s.hits.resize(n);
    s.eye.resize(n);
    s.ao.reset(n * m);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 1);  // the eye ray
    for (uint32_t i = 0; i < n; ++i) s.eye[i] = i;
    intersectAll(context, batch.cameraRays, s.eye, RayKind::Primary, s.hits);
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) continue;
      for (size_t j = 0; j < m; ++j)
        s.ao.prepare(i * m + j, stage2_, *s.hits[i], batch.samples[i].next2D(), aoDistance_);
    }
    s.ao.trace(context);
    for (const uint32_t k : s.ao.traced()) ++batch.rays[k / m];
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) {
        batch.radiance[i] = context.background();
        continue;
      }
      float sum = 0.0f;  // in stage2@ref's order
      for (size_t j = 0; j < m; ++j) sum += s.ao.estimate(i * m + j);
      batch.radiance[i] = Color(sum / aoRays_);
    }
  }

 private:
  struct Scratch {
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<uint32_t> eye;
    AmbientOcclusionWave ao;
  };

  int aoRays_;                     // M
  float aoDistance_;               // D
  const Stage2Functions& stage2_;  // this stage's own functions: the reference's stage 2
};

const bool registered = registerWavefrontStage<WavefrontNestedAmbientOcclusion>(stage2());

}  // namespace
}  // namespace pathway
