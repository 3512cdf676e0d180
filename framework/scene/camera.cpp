#include "scene/camera.h"

#include <cmath>

namespace pathway {

Camera::Camera(const Scene& scene, int width, int height) {
  if (scene.camera) {
    const glm::mat4& m = scene.camera->cameraToWorld;
    setup(Vec3(m[3]), -glm::normalize(Vec3(m[2])), glm::normalize(Vec3(m[1])), scene.camera->yfov,
          width, height);
    return;
  }
  // Default framing: look at the bounds' centre from the +Z side, far enough back that the
  // bounding sphere fits the vertical field of view.
  const float yfov = glm::radians(45.0f);
  const Vec3 center = scene.bounds.center();
  const float radius = std::fmax(0.5f * glm::length(scene.bounds.extent()), 1e-6f);
  const float distance = radius / std::sin(0.5f * yfov);
  setup(center + Vec3(0.0f, 0.0f, distance), Vec3(0.0f, 0.0f, -1.0f), Vec3(0.0f, 1.0f, 0.0f), yfov,
        width, height);
}

Camera::Camera(const Vec3& position, const Vec3& lookAt, const Vec3& up, float yfovRadians,
               int width, int height) {
  setup(position, glm::normalize(lookAt - position), up, yfovRadians, width, height);
}

void Camera::setup(const Vec3& position, const Vec3& forward, const Vec3& up, float yfov, int width,
                   int height) {
  position_ = position;
  forward_ = forward;
  right_ = glm::normalize(glm::cross(forward, up));
  up_ = glm::cross(right_, forward_);
  yfov_ = yfov;
  const float halfHeight = std::tan(0.5f * yfov);
  const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
  topLeft_ = forward_ - halfWidth * right_ + halfHeight * up_;
  pixelRight_ = (2.0f * halfWidth / static_cast<float>(width)) * right_;
  pixelDown_ = (-2.0f * halfHeight / static_cast<float>(height)) * up_;
}

Camera Camera::withImageMoved(Vec2 pixels) const {
  Camera moved = *this;
  moved.topLeft_ -= pixels.x * pixelRight_ + pixels.y * pixelDown_;
  return moved;
}

Ray Camera::generateRay(Vec2 filmPosition) const {
  const Vec3 direction = topLeft_ + filmPosition.x * pixelRight_ + filmPosition.y * pixelDown_;
  return Ray{position_, glm::normalize(direction), kInfinity};
}

}  // namespace pathway
