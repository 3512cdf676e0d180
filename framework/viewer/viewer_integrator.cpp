#include "viewer/viewer_integrator.h"

#include <algorithm>
#include <cmath>

namespace pathway {

ViewerIntegrator::ViewerIntegrator(const Integrator& inner, const CameraPose& pose, int width,
                                   int height, const std::atomic<bool>* cancel)
    : inner_(inner),
      cancel_(cancel),
      width_(width),
      height_(height),
      rays_(new std::atomic<uint64_t>[static_cast<size_t>(width) * height]) {
  // The same basis as Camera::setup.
  forward_ = glm::normalize(pose.lookAt - pose.position);
  right_ = glm::normalize(glm::cross(forward_, pose.up));
  up_ = glm::cross(right_, forward_);
  halfHeight_ = std::tan(0.5f * pose.yfov);
  halfWidth_ = halfHeight_ * static_cast<float>(width) / static_cast<float>(height);
  for (size_t i = 0; i < static_cast<size_t>(width) * height; ++i) rays_[i].store(0);
}

Color ViewerIntegrator::Li(const Ray& cameraRay, SampleStream& samples,
                           RenderContext& context) const {
  if (cancel_ && cancel_->load(std::memory_order_relaxed)) throw PassCancelled{};
  const uint64_t before = context.counters.totalRays();
  const Color radiance = inner_.Li(cameraRay, samples, context);
  const uint64_t traced = context.counters.totalRays() - before;

  // generateRay: direction ∝ forward + x·right + y·up, with x and y linear in the film position.
  const Vec3& d = cameraRay.direction;
  const float depth = glm::dot(d, forward_);
  if (depth > 0.0f) {
    const float x = glm::dot(d, right_) / depth / halfWidth_;
    const float y = glm::dot(d, up_) / depth / halfHeight_;
    const int px =
        std::clamp(static_cast<int>(std::floor((x + 1.0f) * 0.5f * width_)), 0, width_ - 1);
    const int py =
        std::clamp(static_cast<int>(std::floor((1.0f - y) * 0.5f * height_)), 0, height_ - 1);
    rays_[static_cast<size_t>(py) * width_ + px].fetch_add(traced, std::memory_order_relaxed);
  }
  return radiance;
}

}  // namespace pathway
