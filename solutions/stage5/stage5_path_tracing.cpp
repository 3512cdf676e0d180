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
// The maths each part needs is derived in a comment where that part is written: the uniform
// point on a triangle in sampleLight, the area form of direct light in directLightBeforeShadow,
// the path's weights and Russian roulette above Li. Each is written once: the wavefront version
// at the end of the file calls the same functions.
#include <cmath>

#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage5.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// A point on the emitters for NEE: the picker chooses a triangle (by area or by power), then a
// uniform point on it, so the density per area is that triangle's probability over its area.
LightSample sampleLight(const EmitterPicker& lights, float uPick, Vec2 uPoint) {
  const EmitterPicker::Pick pick = lights.pick(uPick);
  const EmissiveTriangle& e = *pick.emitter;
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
  const float s = std::sqrt(uPoint.x);
  const float b0 = 1.0f - s, b1 = uPoint.y * s;
  LightSample light;
  light.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2;
  light.normal = e.normal;
  light.emitter = &e;
  light.pdfArea = pick.probability / e.area;
  return light;
}

// A next-event estimate before its shadow ray is traced.
struct DirectLight {
  Ray shadowRay;
  Color value;  // what it adds when nothing blocks shadowRay
};

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
  // The rule for q and the order of a sample's numbers are the stage 5 README's (the students'
  // statement of them); the code below plays them.
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
      if (depthReached(bounce)) break;

      const Color brdf = hit->albedo * kInvPi;
      if (nextEventEstimation_) radiance += throughput * directLight(*hit, brdf, samples, context);

      const std::optional<Ray> next = continuation(*hit, brdf, bounce, throughput, samples);
      if (!next) break;
      ray = *next;
      kind = RayKind::Secondary;
      addEmission = !nextEventEstimation_;
    }
    return radiance;
  }

  // The steps of Li that the wavefront version (at the end of the file) takes too: each is
  // written once, here.
  bool depthReached(int bounce) const { return maxDepth_ >= 0 && bounce >= maxDepth_; }
  bool nextEventEstimation() const { return nextEventEstimation_; }
  // Next-event estimation at `hit` up to its shadow ray: nothing where the estimate is zero without
  // a ray, otherwise the shadow ray and the light it brings (times the BRDF) when nothing blocks
  // it.
  std::optional<DirectLight> directLightBeforeShadow(const SurfaceHit& hit, const Color& brdf,
                                                     SampleStream& samples) const {
    // Draw the numbers even when there is nothing to sample, so dimensions stay aligned.
    const float uPick = samples.next1D();
    const Vec2 uPoint = samples.next2D();
    if (lights_.empty()) return std::nullopt;
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
    const Vec3 toLight = light.position - hit.position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const Vec3 direction = toLight / std::sqrt(distanceSquared);
    const float cosSurface = glm::dot(hit.normal, direction);
    const float cosLight = glm::dot(light.normal, -direction);
    // A one-sided emitter lights only the side its front face looks at.
    const bool facing = cosLight > 0.0f || light.emitter->doubleSided;
    if (cosSurface <= 0.0f || cosLight == 0.0f || !facing) return std::nullopt;

    const Ray shadowRay = hit.spawnRayTo(light.position, light.normal);
    const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared;
    return DirectLight{shadowRay, light.emitter->emission * brdf * geometry / light.pdfArea};
  }

  // The path's next ray from `hit`, `throughput` taking this bounce's weight (and 1/q where it
  // survives the roulette); nothing where the path ends here.
  std::optional<Ray> continuation(const SurfaceHit& hit, const Color& brdf, int bounce,
                                  Color& throughput, SampleStream& samples) const {
    // One continuation ray, cosine-weighted (stage 2).
    const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D());
    const float pdf = stage2_.cosineHemispherePdf(local.z);
    if (pdf <= 0.0f) return std::nullopt;
    throughput *= brdf * local.z / pdf;

    if (bounce + 1 >= rouletteDepth_) {
      // Russian roulette (derived above Li): survive with q, then divide by q.
      const float q = std::fmin(0.95f, maxComponent(throughput));
      if (samples.next1D() >= q) return std::nullopt;
      throughput /= q;
    }
    return hit.spawnRay(Frame(hit.normal).toWorld(local));
  }

 private:
  // Light arriving at `hit` straight from a point picked on the emitters, times the BRDF.
  Color directLight(const SurfaceHit& hit, const Color& brdf, SampleStream& samples,
                    const RenderContext& context) const {
    const std::optional<DirectLight> light = directLightBeforeShadow(hit, brdf, samples);
    if (!light || context.occluded(light->shadowRay, RayKind::Shadow)) return Color(0.0f);
    return light->value;
  }

  int maxDepth_;  // most bounces; -1: no limit (Russian roulette alone ends paths)
  int rouletteDepth_;
  bool nextEventEstimation_;
  EmitterPicker lights_;
  const Stage2Functions& stage2_;  // stage 2: cosine-weighted directions
};

// Stage 5 hands its light sampling on to the warp test (`pathway warptest --stage 5`).
const bool registered = registerStage<PathTracer>(stage5(), Stage5Functions{sampleLight});

// The wavefront version, "stage5@fast": this path tracer run on a batch of paths at once, for the
// renders that are not student code (references, calibration, charts, cluster renders; never part
// of the exercise). Each bounce of every path still alive is one wave: its rays are traced in
// 16-ray Embree packets, then every path is shaded, then the wave's shadow rays are traced in
// packets. It is the same estimator with the same arithmetic, path by path: the same numbers from
// each sample's stream in the same order, the same expressions, the radiance summed in the same
// order (a bounce's NEE term is added once its shadow ray is answered, before the next bounce's).
// So its image equals stage5@ref's wherever Embree's packets report the hits single rays do
// (test: WavefrontStages.*). Its steps are the path tracer's own (depthReached,
// directLightBeforeShadow, continuation): only the order in which rays are traced is its own.
class WavefrontPathTracer : public WavefrontIntegrator {
 public:
  explicit WavefrontPathTracer(const StageSetup<Stage5Params>& setup) : path_(setup) {}

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size();
    Waves& w = waves(n);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 0);
    w.rays.assign(batch.cameraRays.begin(), batch.cameraRays.end());
    w.throughput.assign(n, Color(1.0f));
    w.active.resize(n);
    for (uint32_t i = 0; i < n; ++i) w.active[i] = i;  // every path starts
    RayKind kind = RayKind::Primary;
    bool addEmission = true;  // camera rays always; bounce rays only when NEE is off

    for (int bounce = 0; !w.active.empty(); ++bounce) {
      intersectAll(context, w.rays, w.active, kind, w.hits);
      w.next.clear();
      w.shadowed.clear();
      for (const uint32_t i : w.active) {
        ++batch.rays[i];
        const std::optional<SurfaceHit>& hit = w.hits[i];
        Color& radiance = batch.radiance[i];
        Color& throughput = w.throughput[i];
        if (!hit) {
          radiance += throughput * context.background();
          continue;
        }
        if (addEmission) radiance += throughput * hit->emitted;
        if (path_.depthReached(bounce)) continue;

        const Color brdf = hit->albedo * kInvPi;
        SampleStream& samples = batch.samples[i];
        if (path_.nextEventEstimation()) {
          w.neeThroughput[i] = throughput;
          if (const auto light = path_.directLightBeforeShadow(*hit, brdf, samples)) {
            w.shadowRays[i] = light->shadowRay;
            w.neeValue[i] = light->value;
            w.shadowed.push_back(i);
          } else {
            radiance += throughput * Color(0.0f);  // as stage5@ref adds a zero term
          }
        }

        const std::optional<Ray> next = path_.continuation(*hit, brdf, bounce, throughput, samples);
        if (!next) continue;
        w.rays[i] = *next;
        w.next.push_back(i);
      }

      occludedAll(context, w.shadowRays, w.shadowed, RayKind::Shadow, w.blocked);
      for (const uint32_t i : w.shadowed) {
        ++batch.rays[i];
        batch.radiance[i] += w.neeThroughput[i] * (w.blocked[i] ? Color(0.0f) : w.neeValue[i]);
      }
      w.active.swap(w.next);
      kind = RayKind::Secondary;
      addEmission = !path_.nextEventEstimation();
    }
  }

 private:
  // Each thread's scratch arrays, kept between batches (no allocation per batch).
  struct Waves {
    std::vector<Ray> rays, shadowRays;
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<Color> throughput, neeThroughput, neeValue;
    std::vector<uint8_t> blocked;
    std::vector<uint32_t> active, next, shadowed;
  };
  static Waves& waves(size_t n) {
    thread_local Waves w;
    if (w.hits.size() < n) {
      w.hits.resize(n);
      w.shadowRays.resize(n);
      w.neeThroughput.resize(n);
      w.neeValue.resize(n);
      w.blocked.resize(n);
    }
    return w;
  }

  PathTracer path_;
};

const bool registeredWavefront = registerWavefrontStage<WavefrontPathTracer>(stage5());

}  // namespace
}  // namespace pathway
