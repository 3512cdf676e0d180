// What a ray query reports about the closest hit, and the new rays that may leave it.
#pragma once

#include <cstdint>

#include "core/math.h"

namespace pathway {

struct SurfaceHit {
  float distance = 0.0f;  // ray parameter t of the hit
  Vec3 position;          // on the triangle, from its barycentric coordinates
  Vec3 normal;            // unit geometric normal, turned to face the incoming ray
  bool frontFace = true;  // the ray hit the counter-clockwise (front) side
  Color albedo{0.0f};     // Lambertian reflectance (factor x texture)
  Color emitted{0.0f};    // radiance emitted back along the ray (zero on a one-sided back face)
  uint32_t mesh = 0;
  uint32_t triangle = 0;

  // A ray leaving this point in `direction` (any length). Its origin is moved off the surface so
  // it cannot hit the surface it starts on; tMax is in units of |direction|.
  Ray spawnRay(const Vec3& direction, float tMax = kInfinity) const {
    const Vec3 side = glm::dot(direction, normal) >= 0.0f ? normal : -normal;
    return Ray{offsetRayOrigin(position, side), direction, tMax};
  }

  // A shadow ray from this point to `target` on another surface with normal `targetNormal`
  // (e.g. a point on a light). Both ends are moved off their surfaces, so neither can block it.
  Ray spawnRayTo(const Vec3& target, const Vec3& targetNormal) const {
    const Vec3 toTarget = target - position;
    const Vec3 side = glm::dot(toTarget, normal) >= 0.0f ? normal : -normal;
    const Vec3 origin = offsetRayOrigin(position, side);
    const Vec3 targetSide = glm::dot(toTarget, targetNormal) <= 0.0f ? targetNormal : -targetNormal;
    const Vec3 end = offsetRayOrigin(target, targetSide);
    // Unnormalised direction: the segment is (0, 1], ending just in front of the target surface.
    return Ray{origin, end - origin, 1.0f};
  }
};

}  // namespace pathway
