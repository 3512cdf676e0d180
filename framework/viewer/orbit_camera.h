// The viewer's camera: it starts as the scene's camera and orbits around a target point in front
// of it (left drag), pans (right/middle drag) and zooms (scroll). Reset returns to the scene's
// camera (up to float rounding), so a reset view shows what `pathway render` renders.
#pragma once

#include "core/math.h"
#include "scene/scene.h"

namespace pathway {

// What the renderer's Camera is built from: Camera(position, lookAt, up, yfov, w, h).
struct CameraPose {
  Vec3 position{0.0f};
  Vec3 lookAt{0.0f, 0.0f, -1.0f};
  Vec3 up{0.0f, 1.0f, 0.0f};
  float yfov = 0.8f;  // radians

  bool operator==(const CameraPose& o) const {
    return position == o.position && lookAt == o.lookAt && up == o.up && yfov == o.yfov;
  }
  bool operator!=(const CameraPose& o) const { return !(*this == o); }
};

class OrbitCamera {
 public:
  OrbitCamera() = default;
  explicit OrbitCamera(const Scene& scene);

  void reset();
  // Mouse motion in pixels; `viewHeight` is the height of the pane in pixels.
  void orbit(float dx, float dy);
  void pan(float dx, float dy, float viewHeight);
  void zoom(float wheelSteps);

  CameraPose pose() const;

 private:
  Vec3 homePosition_{0.0f}, homeForward_{0.0f, 0.0f, -1.0f};
  float homeDistance_ = 1.0f;
  Vec3 up_{0.0f, 1.0f, 0.0f};  // the scene camera's up: the orbit's vertical axis
  float yfov_ = 0.8f;

  Vec3 target_{0.0f, 0.0f, -1.0f};
  Vec3 forward_{0.0f, 0.0f, -1.0f};
  float distance_ = 1.0f;
};

}  // namespace pathway
