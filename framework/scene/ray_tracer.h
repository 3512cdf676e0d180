// The scene's ray queries, answered by an Embree BVH built over the scene's own vertex and index
// arrays (shared, not copied). Every query counts itself in the caller's RayCounters.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "core/math.h"
#include "core/ray_counters.h"
#include "scene/scene.h"
#include "scene/surface_hit.h"

namespace pathway {

// One traced ray, as recorded for benchmarks that replay a render's exact ray mix.
struct LoggedRay {
  Ray ray;
  bool occlusionOnly;        // occluded() rather than intersect()
  bool startsPacket = true;  // the first ray of a packet query, or a single-ray query
};

// What Embree accepts (its Ray::valid(), which its debug builds assert): coordinates within
// about 1.8e18 and a length that is not NaN. Student code can make others (a NaN direction from
// a frame built on a zero vector); every query answers such a ray with "nothing there", so the
// NaN it came from reaches the image, where the grader names it, instead of aborting in Embree.
bool embreeAccepts(const Ray& ray);

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

  // The same queries for up to kPacketSize rays at once, traced together as one Embree packet
  // (rtcIntersect16 / rtcOccluded16): what wavefront renderers use. The packet is the rays
  // rays[which[0]], ..., rays[which[count - 1]] (1 <= count <= kPacketSize, all of one kind);
  // the answer for rays[i] goes to hits[i] / blocked[i], the one the single-ray query gives.
  static constexpr int kPacketSize = 16;
  void intersectPacket(const Ray rays[], const uint32_t which[], int count, RayKind kind,
                       RayCounters& counters, std::optional<SurfaceHit> hits[]) const;
  void occludedPacket(const Ray rays[], const uint32_t which[], int count, RayKind kind,
                      RayCounters& counters, uint8_t blocked[]) const;

  // Records every query into `log` (nullptr: stop). Single-threaded renders only: the log is
  // not synchronised. Benchmarks use it to trace the same rays through raw Embree.
  void setRayLog(std::vector<LoggedRay>* log) { log_ = log; }

  const Scene& scene() const { return scene_; }
  // Scene::contentHash() as it was when the BVH was built (computed once: it reads every vertex).
  uint64_t sceneHash() const { return sceneHash_; }
  size_t bvhBytes() const { return bvhBytes_; }  // memory Embree allocated for the BVH

 private:
  // The hit Embree reported for `ray`: position from the barycentrics, normal facing the ray,
  // material. One function for single rays and packets, so both give the same hit.
  SurfaceHit surfaceHit(const Ray& ray, uint32_t mesh, uint32_t triangle, float t, float u, float v,
                        const Vec3& frontNormal) const;
  void logQueries(const Ray rays[], const uint32_t which[], int count, bool occlusionOnly) const;

  // Embree's scene, kept out of this header so that what includes it (every stage file) does
  // not depend on which Embree the build uses (scene/embree.h).
  struct Bvh;

  const Scene& scene_;
  std::unique_ptr<Bvh> bvh_;
  size_t bvhBytes_ = 0;
  uint64_t sceneHash_ = 0;
  std::vector<LoggedRay>* log_ = nullptr;
};

}  // namespace pathway
