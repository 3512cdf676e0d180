// Stage 2 - ambient occlusion as two nested integrals (reference solution).
//
// For the surface point P seen through the pixel, ambient occlusion is the cosine-weighted
// fraction of the hemisphere that is open within a distance D:
//     AO(P) = (1/π) ∫_Ω V(P, ω) cos θ dω,   V = 1 when a ray of length D from P along ω hits
//     nothing.
// The pixel value is the filtered screen integral of AO (stage 1), so there are two nested 2D
// integrals: for every eye sample, M AO rays. Two knobs (eye samples, M) decide the ray count.
//
// With directions drawn with density p(ω) = cos θ / π, each AO ray's estimate V·cos θ / (π·p)
// is simply V: the cosine and the density cancel.
#include <cmath>

#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage2.h"  // the stage's parameters: setup.params.<field>
#include "stages/stage3.h"  // stage 3's, for its wavefront version (the end of this file)

namespace pathway {
namespace {

// A direction in the local frame (z along the normal) with density cos θ / π, from u in [0,1)^2.
// Why cos θ / π: a density must integrate to 1, and ∫_Ω cos θ dω = π over the hemisphere.
// Malley's method draws it: take a point uniform on the unit disk (density 1/π per unit area)
// and lift it straight up onto the hemisphere. The directions in dω land on a patch of the disk
// of area cos θ dω (their projection along z), so a direction has density (1/π)·cos θ. A uniform
// point on the disk: the share of the disk within radius r is r², so r = √u1 (inverting that
// CDF) and the angle is φ = 2π·u2; lifted, z = √(1 - r²) = cos θ.
Vec3 sampleCosineHemisphere(Vec2 u) {
  const float r = std::sqrt(u.x);
  const float phi = 2.0f * kPi * u.y;
  return Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::fmax(0.0f, 1.0f - u.x)));
}

float cosineHemispherePdf(float cosTheta) {
  return cosTheta > 0.0f ? cosTheta * kInvPi : 0.0f;
}

// One AO direction's estimate V(P, ω)·cos θ / (π·p(ω)), once its ray has told whether it is
// `blocked`; `local` is the direction in the local frame, `pdf` > 0 its density.
// It is the one-sample Monte Carlo estimate g(ω) / p(ω) of AO(P) = ∫_Ω g dω, g = V·cos θ / π.
// Its own function because the wavefront version below uses it too, after tracing many rays.
float ambientOcclusionEstimate(bool blocked, const Vec3& local, float pdf) {
  const float visibility = blocked ? 0.0f : 1.0f;
  return visibility * local.z / (kPi * pdf);
}

// One AO direction from u, traced up to `distance`, and its estimate.
float ambientOcclusionSample(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
                             float distance) {
  const Vec3 local = sampleCosineHemisphere(u);
  const float pdf = cosineHemispherePdf(local.z);
  if (pdf <= 0.0f) return 0.0f;  // a direction in the surface plane carries no weight
  const Vec3 direction = Frame(hit.normal).toWorld(local);
  // A unit direction and tMax = D: the ray looks for blockers up to distance D, no further.
  const Ray aoRay = hit.spawnRay(direction, distance);
  const bool blocked = context.occluded(aoRay, RayKind::Secondary);
  return ambientOcclusionEstimate(blocked, local, pdf);
}

class NestedAmbientOcclusion : public Integrator {
 public:
  explicit NestedAmbientOcclusion(const StageSetup<Stage2Params>& setup)
      : aoRays_(setup.params.aoRays), aoDistance_(setup.params.aoDistance) {}

  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return context.background();
    // The inner integral, AO at P, with M directions, each from its own 2D sample:
    //     AO(P) ≈ (1/M) Σ_k V(P, ω_k)·cos θ_k / (π·p(ω_k));
    // the outer one, over the screen, is stage 1's filtered splat of this value.
    float sum = 0.0f;
    for (int j = 0; j < aoRays_; ++j)
      sum += ambientOcclusionSample(context, *hit, samples.next2D(), aoDistance_);
    return Color(sum / aoRays_);
  }

 private:
  int aoRays_;        // M
  float aoDistance_;  // D
};

// Stage 2 hands its hemisphere sampling and ambientOcclusionSample on to stages 3-5.
const bool registered = registerStage<NestedAmbientOcclusion>(
    stage2(), Stage2Functions{sampleCosineHemisphere, cosineHemispherePdf, ambientOcclusionSample});

// The wavefront version, "stage2@fast", for the renders that are not student code (never part of
// the exercise): the batch's eye rays are traced in 16-ray Embree packets, then its M AO rays per
// hit, all together. Each sample draws the same numbers and sums the same estimates in the same
// order as above, so the images agree wherever packets and single rays report the same hits
// (test: WavefrontStages.*).
//
// It is stage 3's wavefront version, "stage3@fast", too: stage 3's one AO ray per sample, from
// dimensions 2-3 with stage 2's estimate, is this with M = 1. (Stage 3 draws that pair before its
// eye ray and this after a hit; with nothing drawn after it, both hand the same numbers to the
// same rays.)

// ambientOcclusionSample (above), split where its ray is traced.
class AmbientOcclusionWave {
 public:
  // Room for `count` AO estimates, none prepared yet.
  void reset(size_t count) {
    rays_.resize(count);
    local_.resize(count);
    pdf_.resize(count);
    blocked_.resize(count);
    traced_.clear();
  }

  // Estimate k: the direction from `u` around `hit` (stage 2's cosine sampling), its ray up to
  // `distance`. A direction with no density gets no ray; its estimate is 0, as in stage 2.
  void prepare(size_t k, const Stage2Functions& stage2, const SurfaceHit& hit, Vec2 u,
               float distance) {
    local_[k] = stage2.sampleCosineHemisphere(u);
    pdf_[k] = stage2.cosineHemispherePdf(local_[k].z);
    if (pdf_[k] <= 0.0f) return;
    rays_[k] = hit.spawnRay(Frame(hit.normal).toWorld(local_[k]), distance);
    traced_.push_back(static_cast<uint32_t>(k));
  }

  // Traces every prepared ray (AO rays count as secondary rays).
  void trace(const RenderContext& context) {
    occludedAll(context, rays_, traced_, RayKind::Secondary, blocked_);
  }
  const std::vector<uint32_t>& traced() const { return traced_; }

  // Estimate k once traced; 0 where no ray was traced.
  float estimate(size_t k) const {
    return pdf_[k] > 0.0f ? ambientOcclusionEstimate(blocked_[k], local_[k], pdf_[k]) : 0.0f;
  }

 private:
  std::vector<Ray> rays_;
  std::vector<Vec3> local_;
  std::vector<float> pdf_;
  std::vector<uint8_t> blocked_;
  std::vector<uint32_t> traced_;
};

class WavefrontAmbientOcclusion : public WavefrontIntegrator {
 public:
  explicit WavefrontAmbientOcclusion(const StageSetup<Stage2Params>& setup)
      : aoRays_(setup.params.aoRays),
        aoDistance_(setup.params.aoDistance),
        stage2_(setup.kit.stage2()) {}
  // Stage 3: one AO ray per sample (M = 1).
  explicit WavefrontAmbientOcclusion(const StageSetup<Stage3Params>& setup)
      : aoRays_(1), aoDistance_(setup.params.aoDistance), stage2_(setup.kit.stage2()) {}

  // M estimates per sample: fewer samples per batch as M grows, so its AO rays stay in cache.
  size_t batchSize() const override {
    return std::max<size_t>(RayTracer::kPacketSize, kBatchSize / static_cast<size_t>(aoRays_));
  }

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size(), m = static_cast<size_t>(aoRays_);
    thread_local Scratch s;
    s.hits.resize(n);
    s.eye.resize(n);
    s.ao.reset(n * m);
    batch.radiance.assign(n, Color(0.0f));
    batch.rays.assign(n, 1);  // the eye ray
    for (uint32_t i = 0; i < n; ++i) s.eye[i] = i;
    intersectAll(context, batch.cameraRays, s.eye, RayKind::Primary, s.hits);
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) continue;
      for (size_t j = 0; j < m; ++j)
        s.ao.prepare(i * m + j, stage2_, *s.hits[i], batch.samples[i].next2D(), aoDistance_);
    }
    s.ao.trace(context);
    for (const uint32_t k : s.ao.traced()) ++batch.rays[k / m];
    for (uint32_t i = 0; i < n; ++i) {
      if (!s.hits[i]) {
        batch.radiance[i] = context.background();
        continue;
      }
      float sum = 0.0f;  // in stage2@ref's order
      for (size_t j = 0; j < m; ++j) sum += s.ao.estimate(i * m + j);
      batch.radiance[i] = Color(sum / aoRays_);
    }
  }

 private:
  struct Scratch {
    std::vector<std::optional<SurfaceHit>> hits;
    std::vector<uint32_t> eye;
    AmbientOcclusionWave ao;
  };

  int aoRays_;                     // M
  float aoDistance_;               // D
  const Stage2Functions& stage2_;  // the kit's stage 2: the reference's
};

const bool registeredWavefront = registerWavefrontStage<WavefrontAmbientOcclusion>(stage2());
const bool registeredWavefrontStage3 = registerWavefrontStage<WavefrontAmbientOcclusion>(stage3());

}  // namespace
}  // namespace pathway
