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
//    (Multiple importance sampling adds both, weighted to sum to one: README, Yours to choose.)
//  - Russian roulette: after a few bounces a path survives with probability q and its weight is
//    divided by q. The expected value is unchanged, and paths end without a hard depth cut.
//
// The maths each part needs is derived in a comment where that part is written: the uniform
// point on a triangle in sampleLight, the area form of direct light in directLight, the path's
// weights and Russian roulette above Li.
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
  // A uniform point on e from uPoint = (u1, u2). Write a point of the triangle as
  //     y = (1 - s)·p0 + s·((1 - t)·p2 + t·p1),   s, t in [0, 1]:
  // s slides a segment from the corner p0 (s = 0) to the opposite edge (s = 1), t runs along it.
  // The segment at s is s times as long as that edge, so the strip [s, s + ds] has an area
  // proportional to s·ds: for a uniform point, s has the marginal density 2s, not 1. Its CDF is
  // s², so s = √u1 (inverting the CDF), and t = u2 is uniform along the segment. In barycentric
  // coordinates: b0 = 1 - s, b1 = u2·s, b2 = 1 - b0 - b1. (Without the square root the points
  // crowd towards p0.) The point is uniform on e (density 1 / area) and e was picked with
  // pick.probability, so its density per unit area over all emitters is
  //     p_A(y) = pick.probability / e.area.
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

  // The path's weights. At every hit the reflected light ∫_Ω L(ω) · brdf · cos θ dω is
  // estimated with ONE direction ω from stage 2's cosine-weighted sampler: brdf · L(ω) · cos θ /
  // p(ω), where p(ω) = cos θ / π and brdf = ρ/π, so brdf · cos θ / p = ρ. The throughput (what
  // light found further along the path is multiplied by) takes that factor at every bounce, and
  // 1/q at every roulette survival. The sample's value is the sum, over the hits of the path, of
  // throughput · (the emission counted there + the NEE estimate there), plus throughput ·
  // background when the path leaves the scene.
  //
  // Russian roulette. If X estimates the rest of the path, going on with probability q and
  // using X / q (else 0) has the mean q · E[X] / q + (1 - q) · 0 = E[X], for any 0 < q <= 1.
  // The reference's rule for q, and the order in which a sample draws its numbers at every hit,
  // are in README.md beside this file ("Russian roulette", "The order of a sample's numbers").
  //
  // Useful: hit->emitted, hit->albedo, hit->normal; directLight() below (NEE);
  // stage2_.sampleCosineHemisphere(samples.next2D()), stage2_.cosineHemispherePdf(cos θ);
  // Frame(hit->normal).toWorld(local); hit->spawnRay(direction); samples.next1D() and
  // maxComponent(throughput) for Russian roulette; maxDepth_, rouletteDepth_, nextEventEstimation_.
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
      PATHWAY_TODO("the path loop: steps (a) to (e) below, then remove the placeholder lines");
      // TODO (a) Emission: throughput · hit->emitted, for the camera ray always, for a bounce
      //          ray only when NEE is off (NEE has counted that light already).
      // TODO (b) The depth limit: when maxDepth_ >= 0 and bounce >= maxDepth_, the path ends.
      // TODO (c) NEE, when nextEventEstimation_: throughput · directLight(*hit, brdf, ...).
      // TODO (d) One continuation: a cosine-weighted direction from samples.next2D() (your stage
      //          2), the throughput times brdf · cos θ / p(ω), the next ray (RayKind::Secondary).
      // TODO (e) Russian roulette from the rr-depth-th bounce ray on, dividing by q (README).
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

    // Next-event estimation. The light reflected at x straight from the emitters is
    //     L_d = ∫_Ω L_e(ω) · brdf · cos θ_x dω     (over the directions ω that meet an emitter).
    // y comes with a density per unit AREA, so integrate over the emitters' area instead. Seen
    // from x, a patch dA at y, at distance d = |x - y|, whose normal makes the angle θ_y with the
    // line to x, covers the solid angle dω = |cos θ_y| dA / d² (the patch's area across the line
    // of sight, over d²). Hence
    //     L_d = ∫_A L_e · brdf · cos θ_x · |cos θ_y| / d² · V(x, y) dA,
    // and one point y drawn with density p_A(y) estimates it by
    //     L_e · brdf · cos θ_x · |cos θ_y| / (d² · p_A(y)),   or 0 when something blocks x-y.
    // (Said the other way round: per unit solid angle at x, y has density p_A · d² / |cos θ_y|.)
    // Only points in front of the surface count (cos θ_x > 0), and a one-sided emitter lights
    // only the side its front faces (cos θ_y > 0, θ_y measured from light.normal).
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

// Stage 5 hands its light sampling on to the warp test (`pathway warptest --stage 5`).
const bool registered = registerStage<PathTracer>(stage5(), Stage5Functions{sampleLight});

}  // namespace
}  // namespace pathway
