// Stage 5 - path tracing with next-event estimation (your file).
//
// Your part: the three TODOs below (README.md beside this file walks through them).
//
// Stage 4 branched N ways at every hit and exploded. A path tracer follows ONE continuation ray
// per bounce and puts its effort into many camera samples instead: the cost is linear in depth.
// Two more ideas make it practical:
//  - Next-event estimation (NEE): at every hit, also send a shadow ray to a point picked on the
//    emitters. Direct light then no longer depends on a random bounce happening to hit a small
//    light. Because the emitters are now sampled explicitly, emission found by a bounce ray is NOT
//    added again (that would count direct light twice); only emission seen by the camera ray is.
//  - Russian roulette: after a few bounces a path survives with probability q and its weight is
//    divided by q. The expected value is unchanged, and paths end without a hard depth cut.
//
// Direct light from a point y with normal n_y on an emitter, picked with density p_A(y) per area:
//     L_e(y → x) · (ρ/π) · cos θ_x · cos θ_y / |x - y|^2 / p_A(y),   if y is visible from x.
#include <cmath>

#include "render/stage_api.h"
#include "stages/stage5.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// A point on the emitters for NEE. `lights.pick(uPick)` chooses a triangle (by area or by power)
// and tells its probability; the point on that triangle is yours to choose, from uPoint.
LightSample sampleLight(const EmitterPicker& lights, float uPick, Vec2 uPoint) {
  const EmitterPicker::Pick pick = lights.pick(uPick);
  const EmissiveTriangle& e = *pick.emitter;  // corners e.p0, e.p1, e.p2; e.normal, e.area
  PATHWAY_TODO("a uniformly distributed point on triangle e and its density per unit area");
  (void)uPoint;
  LightSample light;  // placeholder: the triangle's first corner, with a made-up density
  light.position = e.p0;
  light.normal = e.normal;
  light.emitter = &e;
  light.pdfArea = 1.0f;
  return light;
}

class PathTracer : public Integrator {
 public:
  explicit PathTracer(const StageSetup<Stage5Params>& setup)
      : maxDepth_(setup.params.maxDepth),
        rouletteDepth_(setup.params.rouletteDepth),
        nextEventEstimation_(setup.params.nextEventEstimation),
        lights_(setup.scene, setup.params.lightPick),
        stage2_(setup.kit.stage2()) {}

  // Useful: hit->emitted, hit->albedo, hit->normal; directLight() below (NEE);
  // stage2_.sampleCosineHemisphere(samples.next2D()), stage2_.cosineHemispherePdf(cos θ);
  // Frame(hit->normal).toWorld(local); hit->spawnRay(direction); samples.next1D() for Russian
  // roulette; maxDepth_, rouletteDepth_, nextEventEstimation_.
  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    Color radiance(0.0f);
    Color throughput(1.0f);  // product of BRDF · cos / pdf (and 1/q) along the path so far
    Ray ray = cameraRay;
    RayKind kind = RayKind::Primary;
    for (int bounce = 0;; ++bounce) {
      const auto hit = context.intersect(ray, kind);
      if (!hit) {
        radiance += throughput * context.background();  // NEE never samples the background
        break;
      }
      PATHWAY_TODO(
          "the path loop: emission (counted once), the depth limit, NEE, one continuation ray "
          "per bounce, Russian roulette with the 1/q weight");
      (void)bounce, (void)samples;
      // Placeholder: the first surface lit from the eye, plus what it emits; the path ends.
      radiance += throughput * eyeLightShading(*hit, ray);
      break;
    }
    return radiance;
  }

 private:
  // Light arriving at `hit` straight from a point picked on the emitters, times the BRDF.
  Color directLight(const SurfaceHit& hit, const Color& brdf, SampleStream& samples,
                    const RenderContext& context) const {
    // Draw the numbers even when there is nothing to sample, so dimensions stay aligned.
    const float uPick = samples.next1D();
    const Vec2 uPoint = samples.next2D();
    if (lights_.empty()) return Color(0.0f);
    const LightSample light = sampleLight(lights_, uPick, uPoint);

    PATHWAY_TODO("direct light: Le * brdf * cos_x * cos_y / (distance^2 * pdfArea) if visible");
    (void)hit, (void)brdf, (void)light, (void)context;
    return Color(0.0f);  // placeholder: no direct light
  }

  int maxDepth_;  // most bounces; -1: no limit (Russian roulette alone ends paths)
  int rouletteDepth_;
  bool nextEventEstimation_;
  EmitterPicker lights_;
  const Stage2Functions& stage2_;  // stage 2: cosine-weighted directions
};

const bool registered = registerStage<PathTracer>(stage5());

}  // namespace
}  // namespace pathway
