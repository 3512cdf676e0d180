// Stage 5's wavefront version, "stage5@fast": the path tracer of stage5_path_tracing.cpp run on a
// batch of paths at once, for the renders that are not student code (references, calibration,
// charts, cluster renders). Each bounce of every path still alive is one wave: its rays are
// traced in 16-ray Embree packets, then every path is shaded, then the wave's shadow rays are
// traced in packets.
//
// It is the same estimator with the same arithmetic, path by path: the same numbers from each
// sample's stream in the same order, the same expressions, the radiance summed in the same order
// (a bounce's NEE term is added once its shadow ray is answered, before the next bounce's). So an
// image it makes equals stage5@ref's wherever Embree's packet traversal reports the same hits as
// its single-ray traversal (test: WavefrontStages.*). A change to stage 5's maths goes in both.
#include <cmath>
#include <numeric>

#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage5.h"

namespace pathway {
namespace {

class WavefrontPathTracer : public WavefrontIntegrator {
 public:
  explicit WavefrontPathTracer(const StageSetup<Stage5Params>& setup)
      : maxDepth_(setup.params.maxDepth),
        rouletteDepth_(setup.params.rouletteDepth),
        nextEventEstimation_(setup.params.nextEventEstimation),
        lights_(setup.scene, setup.params.lightPick),
        stage2_(setup.kit.stage2()) {}

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size();
    Waves& w = waves(n);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 0);
    w.rays.assign(batch.cameraRays.begin(), batch.cameraRays.end());
    w.throughput.assign(n, Color(1.0f));
    w.active.resize(n);
    std::iota(w.active.begin(), w.active.end(), 0u);
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
        if (maxDepth_ >= 0 && bounce >= maxDepth_) continue;

        const Color brdf = hit->albedo * kInvPi;
        SampleStream& samples = batch.samples[i];
        if (nextEventEstimation_) {
          w.neeThroughput[i] = throughput;
          if (prepareDirectLight(*hit, brdf, samples, w.shadowRays[i], w.neeValue[i]))
            w.shadowed.push_back(i);
          else
            radiance += throughput * Color(0.0f);  // as stage5@ref adds a zero term
        }

        const Vec3 local = stage2_.sampleCosineHemisphere(samples.next2D());
        const float pdf = stage2_.cosineHemispherePdf(local.z);
        if (pdf <= 0.0f) continue;
        throughput *= brdf * local.z / pdf;
        if (bounce + 1 >= rouletteDepth_) {
          const float q = std::fmin(0.95f, maxComponent(throughput));
          if (samples.next1D() >= q) continue;
          throughput /= q;
        }
        w.rays[i] = hit->spawnRay(Frame(hit->normal).toWorld(local));
        w.next.push_back(i);
      }

      occludedAll(context, w.shadowRays, w.shadowed, RayKind::Shadow, w.blocked);
      for (const uint32_t i : w.shadowed) {
        ++batch.rays[i];
        batch.radiance[i] += w.neeThroughput[i] * (w.blocked[i] ? Color(0.0f) : w.neeValue[i]);
      }
      w.active.swap(w.next);
      kind = RayKind::Secondary;
      addEmission = !nextEventEstimation_;
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

  // stage5_path_tracing.cpp's directLight up to its shadow ray (derivation there): draws the
  // same numbers, and returns false where it returns zero without a ray. Otherwise `shadowRay`
  // is the ray to trace and `value` the term to add when nothing blocks it.
  bool prepareDirectLight(const SurfaceHit& hit, const Color& brdf, SampleStream& samples,
                          Ray& shadowRay, Color& value) const {
    const float uPick = samples.next1D();
    const Vec2 uPoint = samples.next2D();
    if (lights_.empty()) return false;
    const EmitterPicker::Pick pick = lights_.pick(uPick);
    const EmissiveTriangle& e = *pick.emitter;
    const float s = std::sqrt(uPoint.x);
    const float b0 = 1.0f - s, b1 = uPoint.y * s;
    const Vec3 lightPosition = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2;
    const float pdfArea = pick.probability / e.area;

    const Vec3 toLight = lightPosition - hit.position;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return false;
    const Vec3 direction = toLight / std::sqrt(distanceSquared);
    const float cosSurface = glm::dot(hit.normal, direction);
    const float cosLight = glm::dot(e.normal, -direction);
    const bool facing = cosLight > 0.0f || e.doubleSided;
    if (cosSurface <= 0.0f || cosLight == 0.0f || !facing) return false;

    shadowRay = hit.spawnRayTo(lightPosition, e.normal);
    const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared;
    value = e.emission * brdf * geometry / pdfArea;
    return true;
  }

  int maxDepth_;
  int rouletteDepth_;
  bool nextEventEstimation_;
  EmitterPicker lights_;
  const Stage2Functions& stage2_;
};

const bool registered = registerWavefrontStage<WavefrontPathTracer>(stage5());

}  // namespace
}  // namespace pathway
