// Stage 3 - ambient occlusion as one 4D integral (reference solution).
//
// Stage 2 nested two 2D integrals: screen position outside, hemisphere inside. The same pixel
// value is one integral over the 4D domain screen × hemisphere,
//     I_j = ∫ f_j(x, y) · V(P(x, y), ω) cos θ / π  dx dy dω,
// so one sample is a 4D point (x, y, ω) drawn together, and costs two rays: the eye ray and one AO
// ray. With a 4D low-discrepancy point set (Owen-scrambled Sobol', the default here) the four
// coordinates are stratified jointly, which the nested version cannot do: at equal ray counts the
// 4D estimate is less noisy, and there is one knob (samples per pixel) instead of two.
#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage3.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

class AmbientOcclusion4D : public Integrator {
 public:
  explicit AmbientOcclusion4D(const StageSetup<Stage3Params>& setup)
      : aoDistance_(setup.params.aoDistance), stage2_(setup.kit.stage2()) {}

  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    // Dimensions 0-1 of this sample already placed the eye ray in the pixel (the renderer did
    // that). Draw the AO direction's pair HERE, before the eye ray is traced: draw first, then
    // decide. Every sample then takes dimensions 2-3, the ones stratified together with 0-1 in
    // one 4D point, for the AO direction, whether its eye ray hits or misses (stage 3 README,
    // "How a sample's numbers are handed out"). Nothing is drawn after a miss in this stage, so
    // drawing the pair after the miss test would give the same image; the habit matters once
    // more numbers follow, as in stage 5.
    const Vec2 directionSample = samples.next2D();
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return context.background();
    // One sample's estimate: the pair gives a direction ω with density p(ω) = cos θ / π, and
    // V·cos θ / (π·p(ω)) is the one-sample estimate of AO at the hit (= V: the cosines cancel).
    // Stage 1's splat weighs it by the filter, exactly as in stage 2 with M = 1; only where the
    // numbers come from has changed.
    return Color(stage2_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_));
  }

 private:
  float aoDistance_;               // D
  const Stage2Functions& stage2_;  // stage 2: cosine sampling and the AO estimate
};

const bool registered = registerStage<AmbientOcclusion4D>(stage3());

// The wavefront version, "stage3@fast", for the renders that are not student code (never part of
// the exercise): all the batch's eye rays in 16-ray Embree packets, then all its AO rays. Each
// sample draws the same numbers and computes the same expressions as above with the reference's
// stage 2 (a reference's kit always holds it), so the images agree wherever packets and single
// rays report the same hits (test: WavefrontStages.*).
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
    s.aoRays.resize(n);
    s.cosTheta.resize(n);
    s.pdf.resize(n);
    s.blocked.resize(n);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 1);  // the eye ray
    for (uint32_t i = 0; i < n; ++i) {
      s.directions[i] = batch.samples[i].next2D();  // drawn before the eye ray, as stage3@ref
      s.eye[i] = i;
    }
    intersectAll(context, batch.cameraRays, s.eye, RayKind::Primary, s.hits);
    // Stage 2's ambientOcclusionSample, split where its ray is traced (same arithmetic).
    s.traced.clear();
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) continue;
      const Vec3 local = stage2_.sampleCosineHemisphere(s.directions[i]);
      s.cosTheta[i] = local.z;
      s.pdf[i] = stage2_.cosineHemispherePdf(local.z);
      if (s.pdf[i] <= 0.0f) continue;  // no ray: the estimate is 0
      s.aoRays[i] = s.hits[i]->spawnRay(Frame(s.hits[i]->normal).toWorld(local), aoDistance_);
      s.traced.push_back(i);
    }
    occludedAll(context, s.aoRays, s.traced, RayKind::Secondary, s.blocked);
    for (const uint32_t i : s.traced) ++batch.rays[i];
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) {
        batch.radiance[i] = context.background();
      } else if (s.pdf[i] > 0.0f) {
        const float visibility = s.blocked[i] ? 0.0f : 1.0f;
        batch.radiance[i] = Color(visibility * s.cosTheta[i] / (kPi * s.pdf[i]));
      } else {
        batch.radiance[i] = Color(0.0f);
      }
    }
  }

 private:
  struct Scratch {
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<Vec2> directions;
    std::vector<Ray> aoRays;
    std::vector<float> cosTheta, pdf;
    std::vector<uint8_t> blocked;
    std::vector<uint32_t> eye, traced;
  };

  float aoDistance_;
  const Stage2Functions& stage2_;
};

const bool registeredWavefront = registerWavefrontStage<WavefrontAmbientOcclusion4D>(stage3());

}  // namespace
}  // namespace pathway
