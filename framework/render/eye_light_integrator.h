// Shading for stage 1: a light at the eye. A Lambertian surface looks as bright as
// albedo · |cos θ| (θ between its normal and the view ray); emitters show their emission and rays
// that miss see the background. It has no noise of its own, so all noise comes from the pixel
// integral, which is what stage 1 is about.
#pragma once

#include <cmath>

#include "render/integrator.h"

namespace pathway {

class EyeLightIntegrator : public Integrator {
 public:
  Color Li(const Ray& cameraRay, SampleStream&, RenderContext& context) const override {
    const auto hit = context.tracer.intersect(cameraRay, RayKind::Primary, context.counters);
    if (!hit) return context.scene.background;
    const float cosTheta = std::fabs(glm::dot(hit->normal, glm::normalize(cameraRay.direction)));
    return hit->albedo * cosTheta + hit->emitted;
  }
};

}  // namespace pathway
