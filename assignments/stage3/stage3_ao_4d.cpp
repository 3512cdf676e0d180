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

namespace pathway {
namespace {

class AmbientOcclusion4D : public Integrator {
 public:
  AmbientOcclusion4D(float aoDistance, const StageKit& kit) : aoDistance_(aoDistance), kit_(kit) {}

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    // Dimensions 0-1 of this sample already placed the eye ray in the pixel.
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    PATHWAY_TODO(
        "take the AO direction from dimensions 2-3 of the same sample and return "
        "one AO estimate (your stage 2 function is kit_.ambientOcclusionSample)");
    (void)samples, (void)aoDistance_, (void)kit_;
    // Placeholder: the surface lit from the eye.
    return Color(eyeLightCosine(*hit, cameraRay));
  }

 private:
  float aoDistance_;
  const StageKit& kit_;  // stage 2 of the same variant: cosine sampling and the AO estimate
};

const bool registered = registerIntegrator(
    {variantIntegratorName("stage3", PATHWAY_THIS_VARIANT),
     3,
     PATHWAY_THIS_VARIANT,
     "4D AO: one sample = (x, y, direction) drawn together; one eye ray + one AO ray",
     {{"ao-distance", 0.25, 1e-6, 1e6, false, "D: how far an AO ray looks for blockers"}},
     [](const ParamValues& p, const Scene&) {
       return std::make_unique<AmbientOcclusion4D>(static_cast<float>(p.number("ao-distance")),
                                                   stageKit(PATHWAY_THIS_VARIANT));
     },
     SamplerType::Sobol});

}  // namespace
}  // namespace pathway
