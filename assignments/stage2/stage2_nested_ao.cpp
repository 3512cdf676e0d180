// Stage 2 - ambient occlusion as two nested integrals (your file).
//
// For the surface point P seen through the pixel, ambient occlusion is the cosine-weighted
// fraction of the hemisphere that is open within a distance D:
//     AO(P) = (1/π) ∫_Ω V(P, ω) cos θ dω,   V = 1 when a ray of length D from P along ω hits
//     nothing.
// The pixel value is the filtered screen integral of AO (your stage 1 does the filtering), so
// there are two nested 2D integrals: for every eye sample, M AO rays.
//
// Your part: the four TODOs below (README.md beside this file walks through them).
// Stages 3-5 reuse the first three functions, so get them right here first.
#include <cmath>

#include "render/stage_api.h"
#include "stages/stage2.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// A direction in the local frame (z along the normal) with density cos θ / π, from u in [0,1)^2.
// Why cos θ / π: a density must integrate to 1, and ∫_Ω cos θ dω = π over the hemisphere.
// Malley's method draws it: take a point uniform on the unit disk (density 1/π per unit area)
// and lift it straight up onto the hemisphere. The directions in dω land on a patch of the disk
// of area cos θ dω (their projection along z), so a direction has density (1/π)·cos θ. A uniform
// point on the disk: the share of the disk within radius r is r², so r = √u1 (inverting that
// CDF) and the angle is φ = 2π·u2; lifted, z = √(1 - r²) = cos θ.
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
// It is the one-sample Monte Carlo estimate g(ω) / p(ω) of AO(P) = ∫_Ω g dω, g = V·cos θ / π.
// Useful: Frame(hit.normal).toWorld(local) turns a local direction into a world one;
// hit.spawnRay(direction, tMax) makes a ray that cannot hit its own surface;
// context.occluded(ray, RayKind::Secondary) says whether anything blocks it.
float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                             float distance) {
  PATHWAY_TODO("trace one AO ray of length `distance` and return V cos(theta) / (pi p)");
  (void)context, (void)hit, (void)u, (void)distance;
  return 1.0f;  // placeholder: nothing is ever occluded
}

class NestedAmbientOcclusion : public Integrator {
 public:
  explicit NestedAmbientOcclusion(const StageSetup<Stage2Params>& setup)
      : aoRays_(setup.params.aoRays), aoDistance_(setup.params.aoDistance) {}

  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return context.background();
    // The inner integral, AO at P, with M directions, each from its own 2D sample:
    //     AO(P) ≈ (1/M) Σ_k V(P, ω_k)·cos θ_k / (π·p(ω_k));
    // the outer one, over the screen, is stage 1's filtered splat of this value.
    PATHWAY_TODO("average M = aoRays_ AO samples, each with its own samples.next2D()");
    (void)samples, (void)aoRays_, (void)aoDistance_;
    // Placeholder: the surface lit from the eye, so you can see where the AO will go.
    return Color(eyeLightCosine(*hit, cameraRay));
  }

 private:
  int aoRays_;        // M
  float aoDistance_;  // D
};

// Stage 2 hands its hemisphere sampling and AO estimate on to stages 3-5.
const bool registered = registerStage<NestedAmbientOcclusion>(
    stage2(), Stage2Functions{sampleCosineHemisphere, cosineHemispherePdf, ambientOcclusionSample});

}  // namespace
}  // namespace pathway
