// Stage 2's AO estimate (ambientOcclusionSample in stage2_nested_ao.cpp) for the wavefront
// versions of stages 2 and 3: the same numbers and arithmetic, split where the ray is traced, so
// that a batch's AO rays go out together in Embree packets.
#pragma once

#include <vector>

#include "render/stage_api.h"
#include "render/wavefront.h"

namespace pathway {

class AmbientOcclusionWave {
 public:
  // Room for `count` AO estimates, none prepared yet.
  void reset(size_t count) {
    rays_.resize(count);
    cosTheta_.resize(count);
    pdf_.resize(count);
    blocked_.resize(count);
    traced_.clear();
  }

  // Estimate k: the direction from `u` around `hit` (stage 2's cosine sampling), its ray up to
  // `distance`. A direction with no density gets no ray; its estimate is 0, as in stage 2.
  void prepare(size_t k, const Stage2Functions& stage2, const SurfaceHit& hit, Vec2 u,
               float distance) {
    const Vec3 local = stage2.sampleCosineHemisphere(u);
    cosTheta_[k] = local.z;
    pdf_[k] = stage2.cosineHemispherePdf(local.z);
    if (pdf_[k] <= 0.0f) return;
    rays_[k] = hit.spawnRay(Frame(hit.normal).toWorld(local), distance);
    traced_.push_back(static_cast<uint32_t>(k));
  }

  // Traces every prepared ray (AO rays count as secondary rays).
  void trace(const RenderContext& context) {
    occludedAll(context, rays_, traced_, RayKind::Secondary, blocked_);
  }
  const std::vector<uint32_t>& traced() const { return traced_; }

  // V·cos θ / (π·p(ω)) for estimate k once traced; 0 where no ray was traced.
  float estimate(size_t k) const {
    if (pdf_[k] <= 0.0f) return 0.0f;
    const float visibility = blocked_[k] ? 0.0f : 1.0f;
    return visibility * cosTheta_[k] / (kPi * pdf_[k]);
  }

 private:
  std::vector<Ray> rays_;
  std::vector<float> cosTheta_, pdf_;
  std::vector<uint8_t> blocked_;
  std::vector<uint32_t> traced_;
};

}  // namespace pathway
