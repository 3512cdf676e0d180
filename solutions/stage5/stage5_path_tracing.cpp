// Stage 5 - path tracing with next-event estimation (reference solution).
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
    // Uniform point on a triangle: sqrt warps u so the density per area is constant.
    const float s = std::sqrt(uPoint.x);
    const float b0 = 1.0f - s, b1 = uPoint.y * s;
    LightSample light;
    light.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2;
    light.normal = e.normal;
    light.emitter = &e;
    light.pdfArea = pick_.probability(index) / e.area;
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

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override {
    Color radiance(0.0f);
    Color throughput(1.0f);  // product of BRDF · cos / pdf (and 1/q) along the path so far
    Ray ray = cameraRay;
    RayKind kind = RayKind::Primary;
    bool addEmission = true;  // camera rays always; bounce rays only when NEE is off

    for (int bounce = 0;; ++bounce) {
      const auto hit = context.tracer.intersect(ray, kind, context.counters);
      if (!hit) {
        radiance += throughput * context.scene.background;  // NEE never samples the background
        break;
      }
      if (addEmission) radiance += throughput * hit->emitted;
      if (settings_.maxDepth >= 0 && bounce >= settings_.maxDepth) break;

      const Color brdf = hit->albedo * kInvPi;
      if (settings_.nextEventEstimation)
        radiance += throughput * directLight(*hit, brdf, samples, context);

      // One continuation ray, cosine-weighted (stage 2).
      const Vec3 local = kit_.sampleCosineHemisphere(samples.next2D());
      const float pdf = kit_.cosineHemispherePdf(local.z);
      if (pdf <= 0.0f) break;
      throughput *= brdf * local.z / pdf;

      if (bounce + 1 >= settings_.rouletteDepth) {
        // Survive with q, divide by q: unbiased. q < 1 always, so even albedo 1 paths end.
        const float q = std::fmin(0.95f, maxComponent(throughput));
        if (samples.next1D() >= q) break;
        throughput /= q;
      }
      ray = RayTracer::spawnRay(*hit, Frame(hit->normal).toWorld(local));
      kind = RayKind::Secondary;
      addEmission = !settings_.nextEventEstimation;
    }
    return radiance;
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

    const Vec3 toLight = light.position - hit.position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return Color(0.0f);
    const Vec3 direction = toLight / std::sqrt(distanceSquared);
    const float cosSurface = glm::dot(hit.normal, direction);
    const float cosLight = glm::dot(light.normal, -direction);
    // A one-sided emitter lights only the side its front face looks at.
    const bool facing = cosLight > 0.0f || light.emitter->doubleSided;
    if (cosSurface <= 0.0f || cosLight == 0.0f || !facing) return Color(0.0f);

    const Ray shadowRay = RayTracer::spawnRayTo(hit, light.position, light.normal);
    if (context.tracer.occluded(shadowRay, RayKind::Shadow, context.counters)) return Color(0.0f);
    const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared;
    return light.emitter->emission * brdf * geometry / light.pdfArea;
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
