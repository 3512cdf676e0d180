// The scene's ray queries, answered by an Embree BVH built over the scene's own vertex and index
// arrays (shared, not copied). Every query counts itself in the caller's RayCounters.
#pragma once

#include <embree3/rtcore.h>

#include <optional>
#include <vector>

#include "core/math.h"
#include "core/ray_counters.h"
#include "scene/scene.h"

namespace pathway {

// What an integrator needs to know about the closest hit.
struct SurfaceHit {
  float distance = 0.0f;  // ray parameter t of the hit
  Vec3 position;          // on the triangle, from its barycentric coordinates
  Vec3 normal;            // unit geometric normal, turned to face the incoming ray
  bool frontFace = true;  // the ray hit the counter-clockwise (front) side
  Color albedo{0.0f};     // Lambertian reflectance (factor x texture)
  Color emitted{0.0f};    // radiance emitted back along the ray (zero on a one-sided back face)
  uint32_t mesh = 0;
  uint32_t triangle = 0;
};

// One traced ray, as recorded for benchmarks that replay a render's exact ray mix.
struct LoggedRay {
  Ray ray;
  bool occlusionOnly;  // occluded() rather than intersect()
};

class RayTracer {
 public:
  explicit RayTracer(const Scene& scene);  // builds the BVH; the scene must outlive the tracer
  ~RayTracer();
  RayTracer(const RayTracer&) = delete;
  RayTracer& operator=(const RayTracer&) = delete;

  // Closest hit along the ray in (0, tMax], or nothing.
  std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind, RayCounters& counters) const;
  // True when anything blocks the ray in (0, tMax].
  bool occluded(const Ray& ray, RayKind kind, RayCounters& counters) const;

  // A ray leaving a surface point in `direction` (any length); its origin is moved off the surface
  // so it cannot hit the surface it starts on. tMax is in units of |direction|.
  static Ray spawnRay(const SurfaceHit& from, const Vec3& direction, float tMax = kInfinity) {
    const Vec3 side = glm::dot(direction, from.normal) >= 0.0f ? from.normal : -from.normal;
    return Ray{offsetRayOrigin(from.position, side), direction, tMax};
  }
  // A shadow ray from a surface point to a point on another surface with normal `targetNormal`;
  // both ends are moved off their surfaces so neither surface can block it.
  static Ray spawnRayTo(const SurfaceHit& from, const Vec3& target, const Vec3& targetNormal) {
    const Vec3 toTarget = target - from.position;
    const Vec3 side = glm::dot(toTarget, from.normal) >= 0.0f ? from.normal : -from.normal;
    const Vec3 origin = offsetRayOrigin(from.position, side);
    const Vec3 targetSide = glm::dot(toTarget, targetNormal) <= 0.0f ? targetNormal : -targetNormal;
    const Vec3 end = offsetRayOrigin(target, targetSide);
    // Unnormalised direction: the segment is (0, 1], ending just in front of the target surface.
    return Ray{origin, end - origin, 1.0f};
  }

  // Records every query into `log` (nullptr: stop). Single-threaded renders only: the log is
  // not synchronised. Benchmarks use it to trace the same rays through raw Embree.
  void setRayLog(std::vector<LoggedRay>* log) { log_ = log; }

  const Scene& scene() const { return scene_; }
  size_t bvhBytes() const { return bvhBytes_; }  // memory Embree allocated for the BVH

 private:
  const Scene& scene_;
  RTCDevice device_ = nullptr;
  RTCScene rtcScene_ = nullptr;
  size_t bvhBytes_ = 0;
  std::vector<LoggedRay>* log_ = nullptr;
};

}  // namespace pathway
