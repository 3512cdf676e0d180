// Shading for stage 1: a light at the eye. A Lambertian surface looks as bright as
// albedo · |cos θ| (θ between its normal and the view ray); emitters show their emission and rays
// that miss see the background. It has no noise of its own, so all noise comes from the pixel
// integral, which is what stage 1 is about. The skeletons of later stages show it as their
// placeholder.
#pragma once

#include <cmath>

#include "render/integrator.h"

namespace pathway {

// |cos θ| between the surface normal and the ray that found the hit.
inline float eyeLightCosine(const SurfaceHit& hit, const Ray& ray) {
  return std::fabs(glm::dot(hit.normal, glm::normalize(ray.direction)));
}

// The eye-light picture of a hit.
inline Color eyeLightShading(const SurfaceHit& hit, const Ray& ray) {
  return hit.albedo * eyeLightCosine(hit, ray) + hit.emitted;
}

class EyeLightIntegrator : public Integrator {
 public:
  Color Li(const Ray& cameraRay, SampleStream&, const RenderContext& context) const override {
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return context.background();
    return eyeLightShading(*hit, cameraRay);
  }
};

}  // namespace pathway
