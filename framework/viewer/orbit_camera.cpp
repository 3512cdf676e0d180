#include "viewer/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include "scene/camera.h"

namespace pathway {
namespace {

// Rodrigues' rotation of `v` by `angle` around the unit `axis`.
Vec3 rotate(const Vec3& v, const Vec3& axis, float angle) {
  const float c = std::cos(angle), s = std::sin(angle);
  return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

constexpr float kRadiansPerPixel = 0.005f;

}  // namespace

OrbitCamera::OrbitCamera(const Scene& scene) {
  const Camera camera(scene, 16, 9);  // only its placement is used
  homePosition_ = camera.position();
  homeForward_ = camera.forward();
  yfov_ = camera.yfov();
  if (scene.camera) up_ = glm::normalize(Vec3(scene.camera->cameraToWorld[1]));
  // Orbit around the point in front of the camera as deep as the scene's centre, so that turning
  // keeps the scene in view.
  const float radius = scene.bounds.isEmpty() ? 1.0f : 0.5f * glm::length(scene.bounds.extent());
  const float depth =
      scene.bounds.isEmpty() ? 1.0f : glm::dot(scene.bounds.center() - homePosition_, homeForward_);
  homeDistance_ = std::max(depth, 0.1f * std::max(radius, 1e-3f));
  reset();
}

void OrbitCamera::reset() {
  forward_ = homeForward_;
  distance_ = homeDistance_;
  target_ = homePosition_ + homeForward_ * homeDistance_;
}

void OrbitCamera::orbit(float dx, float dy) {
  // Dragging right turns the scene right: the camera moves left around the target.
  Vec3 forward = rotate(forward_, up_, -dx * kRadiansPerPixel);
  const Vec3 right = glm::normalize(glm::cross(forward, up_));
  const Vec3 pitched = rotate(forward, right, -dy * kRadiansPerPixel);
  // Stop short of the poles, where "up" would no longer define the image's orientation.
  if (std::fabs(glm::dot(pitched, up_)) < 0.995f) forward = pitched;
  forward_ = glm::normalize(forward);
}

void OrbitCamera::pan(float dx, float dy, float viewHeight) {
  const Vec3 right = glm::normalize(glm::cross(forward_, up_));
  const Vec3 up = glm::cross(right, forward_);
  // One pixel covers this much of the plane through the target: the target follows the mouse.
  const float unitsPerPixel =
      2.0f * distance_ * std::tan(0.5f * yfov_) / std::max(viewHeight, 1.0f);
  target_ += (-dx * right + dy * up) * unitsPerPixel;
}

void OrbitCamera::zoom(float wheelSteps) {
  distance_ = std::clamp(distance_ * std::exp(-0.15f * wheelSteps), 1e-4f, 1e6f);
}

CameraPose OrbitCamera::pose() const {
  CameraPose pose;
  pose.position = target_ - forward_ * distance_;
  pose.lookAt = target_;
  pose.up = up_;
  pose.yfov = yfov_;
  return pose;
}

}  // namespace pathway
