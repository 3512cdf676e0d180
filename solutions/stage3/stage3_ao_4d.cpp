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

// Its wavefront version, "stage3@fast", is stage 2's with M = 1 (solutions/stage2): the same
// numbers and the same estimate, so this file keeps the stage's one copy of its maths.

}  // namespace
}  // namespace pathway
