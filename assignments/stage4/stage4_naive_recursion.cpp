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

#include "render/stage_api.h"
#include "stages/stage4.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

class NaiveRecursion : public Integrator {
 public:
  explicit NaiveRecursion(const StageSetup<Stage4Params>& setup)
      : branching_(setup.params.branching),
        depth_(setup.params.depth),
        stage2_(setup.kit.stage2()) {}

  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    return trace(cameraRay, RayKind::Primary, 0, samples, context);
  }

 private:
  // Radiance along `ray`, where `bounce` bounces have happened before it.
  // The estimator: N directions ω_i drawn with density p (stage 2's cosine-weighted sampler),
  //     L(x → v) ≈ E(x → v) + (1/N) Σ_i (ρ/π) · L(x ← ω_i) · cos θ_i / p(ω_i),
  // where each L(x ← ω_i) is the same estimate one bounce deeper (at depth D: emission only).
  // With p = cos θ / π each term is ρ · L(x ← ω_i): the cosine and π cancel against the density.
  // Useful: hit->emitted, hit->albedo, hit->normal; Frame(normal).toWorld(local);
  // your stage 2's stage2_.sampleCosineHemisphere(samples.next2D()) and its density
  // stage2_.cosineHemispherePdf(cos θ); hit->spawnRay(direction); context.intersect(ray, kind)
  // with RayKind::Secondary for every ray after the first.
  Color trace(const Ray& ray, RayKind kind, int bounce, SampleStream& samples,
              const RenderContext& context) const {
    const auto hit = context.intersect(ray, kind);
    if (!hit) return context.background();
    PATHWAY_TODO("emission + the average of N recursive estimates, down to depth D");
    (void)bounce, (void)samples, (void)branching_, (void)depth_, (void)stage2_;
    // Placeholder: the surface lit from the eye, plus what it emits.
    return eyeLightShading(*hit, ray);
  }

  int branching_;                  // N
  int depth_;                      // D
  const Stage2Functions& stage2_;  // stage 2: cosine-weighted directions
};

// The framework refuses settings over the ray budget (parameter max-rays) before this is built.
const bool registered = registerStage<NaiveRecursion>(stage4());

}  // namespace
}  // namespace pathway
