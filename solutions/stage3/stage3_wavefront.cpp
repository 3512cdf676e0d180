// Stage 3's wavefront version, "stage3@fast": 4D AO (stage3_ao_4d.cpp) on a batch of samples at
// once, for the renders that are not student code. All the batch's eye rays are traced in 16-ray
// Embree packets, then all its AO rays. Each sample draws the same numbers and computes the same
// expressions as stage3@ref with the reference's stage 2, so the images agree wherever packets
// and single rays report the same hits (test: WavefrontStages.*). It computes the AO estimate
// itself (../stage2/ao_wavefront.h), to trace the AO rays in packets; a reference's kit always
// holds the reference's stage 2, whose estimate this is.
#include "../stage2/ao_wavefront.h"
#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage3.h"

namespace pathway {
namespace {

class WavefrontAmbientOcclusion4D : public WavefrontIntegrator {
 public:
  explicit WavefrontAmbientOcclusion4D(const StageSetup<Stage3Params>& setup)
      : aoDistance_(setup.params.aoDistance), stage2_(setup.kit.stage2()) {}

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size();
    thread_local Scratch s;
    s.hits.resize(n);
    s.directions.resize(n);
    s.eye.resize(n);
    s.ao.reset(n);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 1);  // the eye ray
    for (uint32_t i = 0; i < n; ++i) {
      s.directions[i] = batch.samples[i].next2D();  // drawn before the eye ray, as stage3@ref
      s.eye[i] = i;
    }
    intersectAll(context, batch.cameraRays, s.eye, RayKind::Primary, s.hits);
    for (uint32_t i = 0; i < n; ++i) {
      if (s.hits[i]) s.ao.prepare(i, stage2_, *s.hits[i], s.directions[i], aoDistance_);
    }
    s.ao.trace(context);
    for (const uint32_t i : s.ao.traced()) ++batch.rays[i];
    for (uint32_t i = 0; i < n; ++i)
      batch.radiance[i] = s.hits[i] ? Color(s.ao.estimate(i)) : context.background();
  }

 private:
  struct Scratch {
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<Vec2> directions;
    std::vector<uint32_t> eye;
    AmbientOcclusionWave ao;
  };

  float aoDistance_;
  const Stage2Functions& stage2_;
};

const bool registered = registerWavefrontStage<WavefrontAmbientOcclusion4D>(stage3());

}  // namespace
}  // namespace pathway
