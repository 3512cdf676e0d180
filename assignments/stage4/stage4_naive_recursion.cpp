// Stage 4 - naive recursive ray tracing (your file).
//
// The rendering equation for Lambertian surfaces (albedo ρ, BRDF ρ/π) with emission E:
//     L(x → v) = E(x → v) + ∫_Ω L(x ← ω) (ρ/π) cos θ dω.
// Knowing the light arriving at x needs the light leaving other points: recursion. The naive
// estimator casts N rays at every hit and recurses into each of them down to a depth D, so one
// camera sample costs 1 + N + N^2 + ... + N^D rays. The framework refuses requests over a ray
// budget (parameter max-rays) before rendering starts.
//
// Your part: the TODO in trace() below (README.md beside this file explains it).
#include <cmath>

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
  // Useful: hit->emitted, hit->albedo, hit->normal; Frame(normal).toWorld(local);
  // kit_.sampleCosineHemisphere(samples.next2D()) and kit_.cosineHemispherePdf(cos θ) (stage 2);
  // RayTracer::spawnRay(*hit, direction); RayKind::Secondary for every ray after the first.
  Color trace(const Ray& ray, RayKind kind, int bounce, SampleStream& samples,
              RenderContext& context) const {
    const auto hit = context.tracer.intersect(ray, kind, context.counters);
    if (!hit) return context.scene.background;
    PATHWAY_TODO("emission + the average of N recursive estimates, down to depth D");
    (void)bounce, (void)samples, (void)branching_, (void)depth_, (void)kit_;
    // Placeholder: the surface lit from the eye, plus what it emits.
    return eyeLightShading(*hit, ray);
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
