// Raw Embree: the scene's own vertex and index arrays in a BVH of its own, traced with
// rtcIntersect1/rtcOccluded1 (or 16 rays at once, rtcIntersect16/rtcOccluded16) and nothing of
// the framework in between. The yardstick the benchmarks hold the framework's ray queries against.
#pragma once

#include <algorithm>

#include "core/error.h"
#include "scene/embree.h"
#include "scene/ray_tracer.h"
#include "scene/scene.h"

namespace pathway::bench {

class RawEmbree {
 public:
  // The default flags are RayTracer's, so that both trace the same kind of BVH; the benchmark
  // of ray queries also measures others (what robust traversal costs, what compact saves).
  explicit RawEmbree(const Scene& s) : RawEmbree(s, bvhFlags(s.triangleCount())) {}
  RawEmbree(const Scene& s, RTCSceneFlags flags) {
    if (!device_) throw PathwayError("could not create an Embree device");
    rtcSetSceneFlags(scene_, flags);
    for (uint32_t i = 0; i < s.meshes.size(); ++i) {
      RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                 s.meshes[i].positions.data(), 0, sizeof(Vec3),
                                 s.meshes[i].positions.size());
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                 s.meshes[i].triangles.data(), 0, sizeof(glm::uvec3),
                                 s.meshes[i].triangles.size());
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(scene_, g, i);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene_);
  }
  ~RawEmbree() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  RawEmbree(const RawEmbree&) = delete;
  RawEmbree& operator=(const RawEmbree&) = delete;

  // Returns the hit distance, or infinity.
  float intersect(const Ray& ray) const {
    RTCRayHit rh;
    rh.ray = toEmbree(ray);
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    embree::intersect1(scene_, rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
  }
  bool occluded(const Ray& ray) const {
    RTCRay r = toEmbree(ray);
    embree::occluded1(scene_, r);
    return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
  }
  // Up to 16 rays at once through rtcIntersect16, Embree's packet traversal: their distances as
  // intersect() gives them.
  void intersect16(const Ray* rays, size_t count, float* distances) const {
    alignas(64) RTCRayHit16 packet;
    alignas(64) int valid[kLanes];
    fillPacket(rays, count, valid, packet.ray);
    for (size_t lane = 0; lane < kLanes; ++lane) {
      packet.hit.geomID[lane] = RTC_INVALID_GEOMETRY_ID;
      packet.hit.instID[0][lane] = RTC_INVALID_GEOMETRY_ID;
    }
    embree::intersect16(valid, scene_, packet);
    for (size_t lane = 0; lane < count; ++lane)
      distances[lane] =
          packet.hit.geomID[lane] == RTC_INVALID_GEOMETRY_ID ? kInfinity : packet.ray.tfar[lane];
  }
  // Up to 16 shadow rays at once through rtcOccluded16: for each, whether it is blocked.
  void occluded16(const Ray* rays, size_t count, bool* blocked) const {
    alignas(64) RTCRay16 packet;
    alignas(64) int valid[kLanes];
    fillPacket(rays, count, valid, packet);
    embree::occluded16(valid, scene_, packet);
    for (size_t lane = 0; lane < count; ++lane) blocked[lane] = packet.tfar[lane] < 0.0f;
  }

  // For code that needs the whole hit record (geometry, primitive, u, v, Ng), such as the raw
  // path tracer: it calls rtcIntersect1/rtcOccluded1 on this BVH itself.
  RTCScene handle() const { return scene_; }

 private:
  static constexpr size_t kLanes = RayTracer::kPacketSize;

  // The first `count` lanes hold the rays; the others repeat the first and are masked off.
  static void fillPacket(const Ray* rays, size_t count, int* valid, RTCRay16& packet) {
    for (size_t lane = 0; lane < kLanes; ++lane) {
      valid[lane] = lane < count ? -1 : 0;  // -1: a ray to trace
      const RTCRay r = toEmbree(rays[lane < count ? lane : 0]);
      packet.org_x[lane] = r.org_x, packet.org_y[lane] = r.org_y, packet.org_z[lane] = r.org_z;
      packet.dir_x[lane] = r.dir_x, packet.dir_y[lane] = r.dir_y, packet.dir_z[lane] = r.dir_z;
      packet.tnear[lane] = r.tnear, packet.tfar[lane] = r.tfar, packet.time[lane] = r.time;
      packet.mask[lane] = r.mask, packet.id[lane] = r.id, packet.flags[lane] = r.flags;
    }
  }

  static RTCRay toEmbree(const Ray& ray) {
    RTCRay r;
    r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
    r.tnear = 0.0f, r.tfar = ray.tMax, r.time = 0.0f;
    r.mask = 0xFFFFFFFFu, r.id = 0, r.flags = 0;
    return r;
  }

  RTCDevice device_ = rtcNewDevice(nullptr);
  RTCScene scene_ = rtcNewScene(device_);
};

}  // namespace pathway::bench
