// Stage 4 - naive recursive ray tracing (reference solution).
//
// The rendering equation for Lambertian surfaces (albedo ρ, BRDF ρ/π) with emission E:
//     L(x → v) = E(x → v) + ∫_Ω L(x ← ω) (ρ/π) cos θ dω.
// Knowing the light arriving at x needs the light leaving other points: recursion. The naive
// estimator casts N rays at every hit and recurses into each of them down to a depth D, so a
// single camera sample costs 1 + N + N^2 + ... + N^D rays. That exponential growth is the point of
// this stage; the framework refuses requests over a ray budget before rendering starts.
//
// With cosine-weighted directions (stage 2), each branch's estimate ρ/π · L · cos θ / p equals
// ρ · L: the cosine and π cancel against the density.
#include "render/ray_budget.h"
#include "render/stage_api.h"

namespace pathway {
namespace {

class NaiveRecursion : public Integrator {
 public:
  NaiveRecursion(int branching, int depth, const StageKit& kit)
      : branching_(branching), depth_(depth), kit_(kit) {}

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    return trace(cameraRay, RayKind::Primary, 0, samples, context);
  }

 private:
  // Radiance along `ray`, where `bounce` bounces have happened before it.
  Color trace(const Ray& ray, RayKind kind, int bounce, SampleStream& samples,
              RenderContext& context) const {
    const auto hit = context.tracer.intersect(ray, kind, context.counters);
    if (!hit) return context.scene.background;
    Color radiance = hit->emitted;
    if (bounce == depth_) return radiance;  // deepest level: emission only

    const Frame frame(hit->normal);
    const Color brdf = hit->albedo * kInvPi;
    Color reflected(0.0f);
    for (int i = 0; i < branching_; ++i) {
      const Vec3 local = kit_.sampleCosineHemisphere(samples.next2D());
      const float pdf = kit_.cosineHemispherePdf(local.z);
      if (pdf <= 0.0f) continue;  // grazing direction: zero contribution, no ray
      const Ray next = RayTracer::spawnRay(*hit, frame.toWorld(local));
      const Color incoming = trace(next, RayKind::Secondary, bounce + 1, samples, context);
      reflected += brdf * incoming * local.z / pdf;
    }
    return radiance + reflected / static_cast<float>(branching_);
  }

  int branching_;
  int depth_;
  const StageKit& kit_;  // stage 2 of the same variant: cosine-weighted directions
};

const bool registered = registerIntegrator(
    {variantIntegratorName("stage4", PATHWAY_THIS_VARIANT),
     4,
     PATHWAY_THIS_VARIANT,
     "naive recursive tracing: N random rays at every hit, down to depth D",
     {{"branching", 3, 1, 1024, true, "N: rays cast at every hit"},
      {"depth", 2, 0, 64, true, "D: bounces; 0 shows emitters only, 1 adds direct light"},
      {"max-rays", 1e6, 1, 1e12, true, "refuse settings that cast more rays per camera sample"}},
     [](const ParamValues& p, const Scene&) {
       const std::string name = variantIntegratorName("stage4", PATHWAY_THIS_VARIANT);
       checkRayBudget(name, p.integer("branching"), p.integer("depth"),
                      static_cast<uint64_t>(p.number("max-rays")));
       return std::make_unique<NaiveRecursion>(p.integer("branching"), p.integer("depth"),
                                               stageKit(PATHWAY_THIS_VARIANT));
     }});

}  // namespace
}  // namespace pathway
