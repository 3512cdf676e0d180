// Stage 3 - ambient occlusion as one 4D integral (your file).
//
// Stage 2 nested two 2D integrals: screen position outside, hemisphere inside. The same pixel
// value is one integral over the 4D domain screen × hemisphere,
//     I_j = ∫ f_j(x, y) · V(P(x, y), ω) cos θ / π  dx dy dω,
// so one sample is a 4D point (x, y, ω) drawn together, and costs two rays: the eye ray and one AO
// ray. The default sampler here is Owen-scrambled Sobol': its 4D points are stratified in all four
// coordinates at once.
//
// Your part: the TODO in Li below (README.md beside this file explains it).
#include <cmath>

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
    // that); the AO direction takes dimensions 2-3, stratified with them in one 4D point. Draw
    // the pair HERE, before the eye ray is traced, because a dimension must mean the same thing
    // in every sample whatever its rays hit (stage 3 README, "How a sample's numbers are handed
    // out"), and drawing before deciding is what keeps that true once a miss or a depth limit
    // would otherwise skip draws, as in stage 5.
    PATHWAY_TODO(
        "draw the AO direction's pair here (dimensions 2-3 of the same sample), then return one "
        "AO estimate below (your stage 2 function is stage2_.ambientOcclusionSample)");
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return context.background();
    // One sample's estimate: the pair gives a direction ω with density p(ω) = cos θ / π, and
    // V·cos θ / (π·p(ω)) is the one-sample estimate of AO at the hit (= V: the cosines cancel).
    // Stage 1's splat weighs it by the filter, exactly as in stage 2 with M = 1; only where the
    // numbers come from has changed.
    (void)samples, (void)aoDistance_, (void)stage2_;
    // Placeholder: the surface lit from the eye. Replace it with the AO estimate.
    return Color(eyeLightCosine(*hit, cameraRay));
  }

 private:
  float aoDistance_;               // D
  const Stage2Functions& stage2_;  // stage 2: cosine sampling and the AO estimate
};

const bool registered = registerStage<AmbientOcclusion4D>(stage3());

}  // namespace
}  // namespace pathway
