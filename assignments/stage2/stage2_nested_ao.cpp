// Stage 2 - ambient occlusion as two nested integrals (your file).
//
// For the surface point P seen through the pixel, ambient occlusion is the cosine-weighted
// fraction of the hemisphere that is open within a distance D:
//     AO(P) = (1/π) ∫_Ω V(P, ω) cos θ dω,   V = 1 when a ray of length D from P along ω hits
//     nothing.
// The pixel value is the filtered screen integral of AO (your stage 1 does the filtering), so
// there are two nested 2D integrals: for every eye sample, M AO rays.
//
// Your part: the three TODOs below (README.md beside this file walks through them).
// Stages 3-5 reuse these functions, so get them right here first.
#include <cmath>

#include "render/stage_api.h"

namespace pathway {
namespace {

// A direction in the local frame (z along the normal) with density cos θ / π, from u in [0,1)^2.
Vec3 sampleCosineHemisphere(Vec2 u) {
  PATHWAY_TODO("cosine-weighted hemisphere sampling (e.g. Malley's method, see README.md)");
  (void)u;
  return Vec3(0.0f, 0.0f, 1.0f);  // placeholder: always straight up
}

// The density of sampleCosineHemisphere's directions, per unit solid angle.
float cosineHemispherePdf(float cosTheta) {
  PATHWAY_TODO("the pdf of your hemisphere sampling");
  return cosTheta > 0.0f ? 1.0f : 0.0f;  // placeholder
}

// One AO direction's estimate V(P, ω)·cos θ / (π·p(ω)).
// Useful: Frame(hit.normal).toWorld(local) turns a local direction into a world one;
// RayTracer::spawnRay(hit, direction, tMax) makes a ray that cannot hit its own surface;
// context.tracer.occluded(ray, RayKind::Secondary, context.counters) says whether it is blocked.
float ambientOcclusionSample(RenderContext& context, const SurfaceHit& hit, Vec2 u,
                             float distance) {
  PATHWAY_TODO("trace one AO ray of length `distance` and return V cos(theta) / (pi p)");
  (void)context, (void)hit, (void)u, (void)distance;
  return 1.0f;  // placeholder: nothing is ever occluded
}

class NestedAmbientOcclusion : public Integrator {
 public:
  NestedAmbientOcclusion(int aoRays, float aoDistance) : aoRays_(aoRays), aoDistance_(aoDistance) {}

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    PATHWAY_TODO("average M = aoRays_ AO samples, each with its own samples.next2D()");
    (void)samples;
    // Placeholder: the surface lit from the eye, so you can see where the AO will go.
    return Color(eyeLightCosine(*hit, cameraRay));
  }

 private:
  int aoRays_;
  float aoDistance_;
};

const bool registered = [] {
  StageKit& kit = stageKit(PATHWAY_THIS_VARIANT);
  kit.sampleCosineHemisphere = sampleCosineHemisphere;
  kit.cosineHemispherePdf = cosineHemispherePdf;
  kit.ambientOcclusionSample = ambientOcclusionSample;
  return registerIntegrator(
      {variantIntegratorName("stage2", PATHWAY_THIS_VARIANT),
       2,
       PATHWAY_THIS_VARIANT,
       "nested AO: per eye sample, M cosine-weighted AO rays of length D",
       {{"ao-rays", 4, 1, 1024, true, "M: AO rays per eye sample"},
        {"ao-distance", 0.25, 1e-6, 1e6, false, "D: how far an AO ray looks for blockers"}},
       [](const ParamValues& p, const Scene&) {
         return std::make_unique<NestedAmbientOcclusion>(
             p.integer("ao-rays"), static_cast<float>(p.number("ao-distance")));
       }});
}();

}  // namespace
}  // namespace pathway
