// Stage 3's wavefront version, "stage3@fast": 4D AO (stage3_ao_4d.cpp) on a batch of samples at
// once, for the renders that are not student code. All the batch's eye rays are traced in 16-ray
// Embree packets, then all its AO rays. Each sample draws the same numbers and computes the same
// expressions as stage3@ref with the reference's stage 2 (ambientOcclusionSample in
// stage2_nested_ao.cpp), so the images agree wherever packets and single rays report the same
// hits (test: WavefrontStages.*). It computes the AO estimate itself, to trace the AO rays in
// packets; a reference's kit always holds the reference's stage 2, whose estimate this is.
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
    s.aoRays.resize(n);
    s.blocked.resize(n);
    s.directions.resize(n);
    s.cosTheta.resize(n);
    s.pdf.resize(n);
    s.eye.clear();
    s.traced.clear();
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 1);  // the eye ray
    for (uint32_t i = 0; i < n; ++i) {
      s.directions[i] = batch.samples[i].next2D();  // drawn before the eye ray, as stage3@ref
      s.eye.push_back(i);
    }
    intersectAll(context, batch.cameraRays, s.eye, RayKind::Primary, s.hits);
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) {
        batch.radiance[i] = context.background();
        continue;
      }
      const Vec3 local = stage2_.sampleCosineHemisphere(s.directions[i]);
      s.cosTheta[i] = local.z;
      s.pdf[i] = stage2_.cosineHemispherePdf(local.z);
      if (s.pdf[i] <= 0.0f) continue;  // no ray: the estimate is 0
      s.aoRays[i] = s.hits[i]->spawnRay(Frame(s.hits[i]->normal).toWorld(local), aoDistance_);
      s.traced.push_back(i);
    }
    occludedAll(context, s.aoRays, s.traced, RayKind::Secondary, s.blocked);
    for (const uint32_t i : s.traced) {
      ++batch.rays[i];
      const float visibility = s.blocked[i] ? 0.0f : 1.0f;
      batch.radiance[i] = Color(visibility * s.cosTheta[i] / (kPi * s.pdf[i]));
    }
  }

 private:
  struct Scratch {
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<Ray> aoRays;
    std::vector<uint8_t> blocked;
    std::vector<Vec2> directions;
    std::vector<float> cosTheta, pdf;
    std::vector<uint32_t> eye, traced;
  };

  float aoDistance_;
  const Stage2Functions& stage2_;
};

const bool registered = registerWavefrontStage<WavefrontAmbientOcclusion4D>(stage3());

}  // namespace
}  // namespace pathway
