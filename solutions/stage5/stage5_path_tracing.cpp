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
#include "stages/stage5.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// A point on the emitters for NEE: the picker chooses a triangle (by area or by power), then a
// uniform point on it, so the density per area is that triangle's probability over its area.
LightSample sampleLight(const EmitterPicker& lights, float uPick, Vec2 uPoint) {
  const EmitterPicker::Pick pick = lights.pick(uPick);
  const EmissiveTriangle& e = *pick.emitter;
  // Uniform point on a triangle: sqrt warps u so the density per area is constant.
  const float s = std::sqrt(uPoint.x);
  const float b0 = 1.0f - s, b1 = uPoint.y * s;
  LightSample light;
  light.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2;
  light.normal = e.normal;
  light.emitter = &e;
  light.pdfArea = pick.probability / e.area;
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

  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    Color radiance(0.0f);
    Color throughput(1.0f);  // product of BRDF · cos / pdf (and 1/q) along the path so far
    Ray ray = cameraRay;
    RayKind kind = RayKind::Primary;
    bool addEmission = true;  // camera rays always; bounce rays only when NEE is off

    for (int bounce = 0;; ++bounce) {
      const auto hit = context.intersect(ray, kind);
      if (!hit) {
        radiance += throughput * context.background();  // NEE never samples the background
        break;
      }
      if (addEmission) radiance += throughput * hit->emitted;
      if (maxDepth_ >= 0 && bounce >= maxDepth_) break;

      const Color brdf = hit->albedo * kInvPi;
      if (nextEventEstimation_) radiance += throughput * directLight(*hit, brdf, samples, context);

      // One continuation ray, cosine-weighted (stage 2).
      const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D());
      const float pdf = stage2_.cosineHemispherePdf(local.z);
      if (pdf <= 0.0f) break;
      throughput *= brdf * local.z / pdf;

      if (bounce + 1 >= rouletteDepth_) {
        // Survive with q, divide by q: unbiased. q < 1 always, so even albedo 1 paths end.
        const float q = std::fmin(0.95f, maxComponent(throughput));
        if (samples.next1D() >= q) break;
        throughput /= q;
      }
      ray = hit->spawnRay(Frame(hit->normal).toWorld(local));
      kind = RayKind::Secondary;
      addEmission = !nextEventEstimation_;
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

    const Vec3 toLight = light.position - hit.position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return Color(0.0f);
    const Vec3 direction = toLight / std::sqrt(distanceSquared);
    const float cosSurface = glm::dot(hit.normal, direction);
    const float cosLight = glm::dot(light.normal, -direction);
    // A one-sided emitter lights only the side its front face looks at.
    const bool facing = cosLight > 0.0f || light.emitter->doubleSided;
    if (cosSurface <= 0.0f || cosLight == 0.0f || !facing) return Color(0.0f);

    const Ray shadowRay = hit.spawnRayTo(light.position, light.normal);
    if (context.occluded(shadowRay, RayKind::Shadow)) return Color(0.0f);
    const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared;
    return light.emitter->emission * brdf * geometry / light.pdfArea;
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
