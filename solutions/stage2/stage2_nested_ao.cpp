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

namespace pathway {
namespace {

// Malley's method: a uniform point on the unit disk, lifted onto the hemisphere, has density
// cos θ / π. r = sqrt(u1) makes the disk point uniform in area.
Vec3 sampleCosineHemisphere(Vec2 u) {
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)));
}

float cosineHemispherePdf(float cosTheta) {
  return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f;
}

// One AO direction: V(P, ω)·cos θ / (π·p(ω)).
float ambientOcclusionSample(RenderContext& context, const SurfaceHit& hit, Vec2 u,
                             float distance) {
  const Vec3 local = sampleCosineHemisphere(u);
  const float pdf = cosineHemispherePdf(local.z);
  if (pdf <= 0.0f) return 0.0f;  // a direction in the surface plane carries no weight
  const Vec3 direction = Frame(hit.normal).toWorld(local);
  // A unit direction and tMax = D: the ray looks for blockers up to distance D, no further.
  const Ray aoRay = RayTracer::spawnRay(hit, direction, distance);
  const bool blocked = context.tracer.occluded(aoRay, RayKind::Secondary, context.counters);
  const float visibility = blocked ? 0.0f : 1.0f;
  return visibility * local.z / (kPi * pdf);
}

class NestedAmbientOcclusion : public Integrator {
 public:
  NestedAmbientOcclusion(int aoRays, float aoDistance) : aoRays_(aoRays), aoDistance_(aoDistance) {}

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    // The inner integral: M directions for this one eye sample, each with its own 2D sample.
    float sum = 0.0f;
    for (int j = 0; j < aoRays_; ++j)
      sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_);
    return Color(sum / aoRays_);
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
