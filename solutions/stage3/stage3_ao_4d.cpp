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

namespace pathway {
namespace {

class AmbientOcclusion4D : public Integrator {
 public:
  AmbientOcclusion4D(float aoDistance, const StageKit& kit) : aoDistance_(aoDistance), kit_(kit) {}

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    // Dimensions 0-1 of this sample placed the eye ray in the pixel (the renderer did that);
    // dimensions 2-3 of the SAME 4D point choose the AO direction.
    const Vec2 directionSample = samples.next2D();
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    return Color(kit_.ambientOcclusionSample(context, *hit, directionSample, aoDistance_));
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
