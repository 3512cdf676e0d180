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
#include "sampling/discrete_distribution.h"
#include "scene/emitters.h"

namespace pathway {
namespace {

struct LightSample {
  Vec3 position;
  Vec3 normal;  // the emitter's front-face normal
  const EmissiveTriangle* emitter = nullptr;
  float pdfArea = 0.0f;  // density of this point per unit area over all emitters
};

// Picks an emitting triangle (by area or by power) and a uniform point on it.
class LightSampler {
 public:
  LightSampler(const Scene& scene, bool powerWeighted)
      : emitters_(collectEmissiveTriangles(scene)) {
    std::vector<double> weights;
    for (const EmissiveTriangle& e : emitters_) {
      const Color power = e.power();
      weights.push_back(powerWeighted ? (power.x + power.y + power.z) / 3.0 : e.area);
    }
    pick_ = DiscreteDistribution(weights);
  }

  bool empty() const { return pick_.empty(); }

  LightSample sample(float uPick, Vec2 uPoint) const {
    const size_t index = pick_.sample(uPick);
    const EmissiveTriangle& e = emitters_[index];
    PATHWAY_TODO("a uniformly distributed point on triangle e and its density per unit area");
    (void)uPoint;
    LightSample light;  // placeholder: the triangle's first corner, with a made-up density
    light.position = e.p0;
    light.normal = e.normal;
    light.emitter = &e;
    light.pdfArea = 1.0f;
    return light;
  }

 private:
  std::vector<EmissiveTriangle> emitters_;
  DiscreteDistribution pick_;
};

struct PathSettings {
  int maxDepth;  // most bounces; -1: no limit (Russian roulette alone ends paths)
  int rouletteDepth;
  bool nextEventEstimation;
  bool powerWeightedLights;
};

class PathTracer : public Integrator {
 public:
  PathTracer(const Scene& scene, const PathSettings& settings, const StageKit& kit)
      : settings_(settings), lights_(scene, settings.powerWeightedLights), kit_(kit) {}

  // Useful: hit->emitted, hit->albedo, hit->normal; directLight() below (NEE);
  // kit_.sampleCosineHemisphere(samples.next2D()), kit_.cosineHemispherePdf(cos θ) (stage 2);
  // RayTracer::spawnRay(*hit, direction); samples.next1D() for Russian roulette;
  // settings_.maxDepth, settings_.rouletteDepth, settings_.nextEventEstimation.
  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    PATHWAY_TODO(
        "the path loop: emission (counted once), NEE, one continuation ray per bounce, "
        "Russian roulette with the 1/q weight");
    (void)samples;
    // Placeholder: the surface lit from the eye, plus what it emits.
    return eyeLightShading(*hit, cameraRay);
  }

 private:
  // Light arriving at `hit` straight from a point picked on the emitters, times the BRDF.
  Color directLight(const SurfaceHit& hit, const Color& brdf, SampleStream& samples,
                    RenderContext& context) const {
    // Draw the numbers even when there is nothing to sample, so dimensions stay aligned.
    const float uPick = samples.next1D();
    const Vec2 uPoint = samples.next2D();
    if (lights_.empty()) return Color(0.0f);
    const LightSample light = lights_.sample(uPick, uPoint);

    PATHWAY_TODO("direct light: Le * brdf * cos_x * cos_y / (distance^2 * pdfArea) if visible");
    (void)hit, (void)brdf, (void)light, (void)context;
    return Color(0.0f);  // placeholder: no direct light
  }

  PathSettings settings_;
  LightSampler lights_;
  const StageKit& kit_;  // stage 2 of the same variant: cosine-weighted directions
};

const bool registered = registerIntegrator(
    {variantIntegratorName("stage5", PATHWAY_THIS_VARIANT),
     5,
     PATHWAY_THIS_VARIANT,
     "path tracing: one ray per bounce, next-event estimation, Russian roulette",
     {{"max-depth", 5, -1, 1000, true,
       "most bounces a path takes (0: emitters only, 1: direct light; -1: no limit)"},
      {"rr-depth", 3, 0, 1000, true, "bounces before Russian roulette starts"},
      {"nee", 1, 0, 1, true, "1: shadow rays to the emitters; 0: only bounces find light"},
      {"light-pick", 1, 0, 1, true, "how NEE picks an emitter: 0 by area, 1 by power"}},
     [](const ParamValues& p, const Scene& scene) {
       const PathSettings settings{p.integer("max-depth"), p.integer("rr-depth"), p.flag("nee"),
                                   p.flag("light-pick")};
       return std::make_unique<PathTracer>(scene, settings, stageKit(PATHWAY_THIS_VARIANT));
     }});

}  // namespace
}  // namespace pathway
