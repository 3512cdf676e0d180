// Stage 2 - ambient occlusion as two nested integrals (reference solution).
//
// For the surface point P seen through the pixel, ambient occlusion is the cosine-weighted
// fraction of the hemisphere that is open within a distance D:
//     AO(P) = (1/π) ∫_Ω V(P, ω) cos θ dω,   V = 1 when a ray of length D from P along ω hits
//     nothing.
// The pixel value is the filtered screen integral of AO (stage 1), so there are two nested 2D
// integrals: for every eye sample, M AO rays. Two knobs (eye samples, M) decide the ray count.
//
// With directions drawn with density p(ω) = cos θ / π, each AO ray's estimate V·cos θ / (π·p)
// is simply V: the cosine and the density cancel.
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
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)));
}

float cosineHemispherePdf(float cosTheta) {
  return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f;
}

// One AO direction's estimate V(P, ω)·cos θ / (π·p(ω)).
// It is the one-sample Monte Carlo estimate g(ω) / p(ω) of AO(P) = ∫_Ω g dω, g = V·cos θ / π.
float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                             float distance) {
  const Vec3 local = sampleCosineHemisphere(u);
  const float pdf = cosineHemispherePdf(local.z);
  if (pdf <= 0.0f) return 0.0f;  // a direction in the surface plane carries no weight
  const Vec3 direction = Frame(hit.normal).toWorld(local);
  // A unit direction and tMax = D: the ray looks for blockers up to distance D, no further.
  const Ray aoRay = hit.spawnRay(direction, distance);
  const bool blocked = context.occluded(aoRay, RayKind::Secondary);
  const float visibility = blocked ? 0.0f : 1.0f;
  return visibility * local.z / (kPi * pdf);
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
    float sum = 0.0f;
    for (int j = 0; j < aoRays_; ++j)
      sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_);
    return Color(sum / aoRays_);
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
