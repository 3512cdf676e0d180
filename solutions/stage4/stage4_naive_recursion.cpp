// Stage 4 - naive recursive ray tracing (reference solution).
//
// The rendering equation for Lambertian surfaces (albedo ρ, BRDF ρ/π) with emission E:
//     L(x → v) = E(x → v) + ∫_Ω L(x ← ω) (ρ/π) cos θ dω.
// Knowing the light arriving at x needs the light leaving other points: recursion. The naive
// estimator casts N rays at every hit and recurses into each of them down to a depth D, so a
// single camera sample costs 1 + N + N^2 + ... + N^D rays. That exponential growth is the point of
// this stage; the framework refuses requests over a ray budget before rendering starts.
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
  Color trace(const Ray& ray, RayKind kind, int bounce, SampleStream& samples,
              const RenderContext& context) const {
    const auto hit = context.intersect(ray, kind);
    if (!hit) return context.background();
    Color radiance = hit->emitted;
    if (bounce == depth_) return radiance;  // deepest level: emission only

    const Frame frame(hit->normal);
    const Color brdf = hit->albedo * kInvPi;
    Color reflected(0.0f);
    for (int i = 0; i < branching_; ++i) {
      const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D());
      const float pdf = stage2_.cosineHemispherePdf(local.z);
      if (pdf <= 0.0f) continue;  // grazing direction: zero contribution, no ray
      const Ray next = hit->spawnRay(frame.toWorld(local));
      const Color incoming = trace(next, RayKind::Secondary, bounce + 1, samples, context);
      reflected += brdf * incoming * local.z / pdf;
    }
    return radiance + reflected / static_cast<float>(branching_);
  }

  int branching_;                  // N
  int depth_;                      // D
  const Stage2Functions& stage2_;  // stage 2: cosine-weighted directions
};

// The framework refuses settings over the ray budget (parameter max-rays) before this is built.
const bool registered = registerStage<NaiveRecursion>(stage4());

}  // namespace
}  // namespace pathway
