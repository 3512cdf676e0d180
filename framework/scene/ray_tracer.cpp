#include "scene/ray_tracer.h"

#include <atomic>
#include <cmath>
#include <string>

#include "core/error.h"
#include "scene/embree.h"

namespace pathway {

bool embreeAccepts(const Ray& ray) {
  constexpr float kLargest = 1.844e18f;  // Embree's FLT_LARGE
  for (int axis = 0; axis < 3; ++axis)
    if (!(std::fabs(ray.origin[axis]) <= kLargest) || !(std::fabs(ray.direction[axis]) <= kLargest))
      return false;
  return !std::isnan(ray.tMax);
}

namespace {

struct DeviceState {
  std::atomic<long long> bytes{0};  // Embree's own allocations, from its memory monitor
  std::string error;                // first error Embree reported
};

void onEmbreeError(void* userPtr, RTCError code, const char* message) {
  auto* state = static_cast<DeviceState*>(userPtr);
  if (state->error.empty())
    state->error = "Embree error " + std::to_string(static_cast<int>(code)) + ": " +
                   (message ? message : "(no message)");
}

bool onEmbreeMemory(void* userPtr, ssize_t bytes, bool /*post*/) {
  static_cast<DeviceState*>(userPtr)->bytes += bytes;
  return true;
}

// One device per process: Embree's thread pool and memory monitor are shared by all scenes.
DeviceState deviceState;
RTCDevice sharedDevice() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw PathwayError("could not create an Embree device");
    rtcSetDeviceErrorFunction(d, onEmbreeError, &deviceState);
    rtcSetDeviceMemoryMonitorFunction(d, onEmbreeMemory, &deviceState);
    return d;
  }();
  return device;
}

void throwIfEmbreeFailed(const std::string& what) {
  if (!deviceState.error.empty()) {
    std::string message = what + ": " + deviceState.error;
    deviceState.error.clear();
    throw PathwayError(message);
  }
}

}  // namespace

RTCSceneFlags bvhFlags(size_t triangles) {
  // Robust always. Compact nodes save memory per triangle but trace slower
  // (docs/benchmarks.md), so only scenes large enough for memory to matter get them.
  return triangles >= kCompactBvhFromTriangles ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT
                                               : RTC_SCENE_FLAG_ROBUST;
}

namespace {

RTCRay toEmbree(const Ray& ray) {
  RTCRay r;
  r.org_x = ray.origin.x;
  r.org_y = ray.origin.y;
  r.org_z = ray.origin.z;
  r.dir_x = ray.direction.x;
  r.dir_y = ray.direction.y;
  r.dir_z = ray.direction.z;
  r.tnear = 0.0f;
  r.tfar = ray.tMax;
  r.time = 0.0f;
  r.mask = 0xFFFFFFFFu;
  r.id = 0;
  r.flags = 0;
  return r;
}

}  // namespace

struct RayTracer::Bvh {
  RTCScene scene = nullptr;
  ~Bvh() {
    if (scene) rtcReleaseScene(scene);
  }
};

RayTracer::RayTracer(const Scene& scene)
    : scene_(scene), bvh_(std::make_unique<Bvh>()), sceneHash_(scene.contentHash()) {
  RTCDevice device = sharedDevice();
  const long long bytesBefore = deviceState.bytes.load();
  RTCScene rtcScene = bvh_->scene = rtcNewScene(device);
  // Robust traversal: rays through shared edges never slip between two triangles, which matters
  // for closed scenes such as the furnace (exactly at a vertex a few still can: see
  // RayTracer.RaysAimedAtSharedEdgesAlwaysHitAndAtVerticesNearlyAlways).
  rtcSetSceneFlags(rtcScene, bvhFlags(scene.triangleCount()));
  for (uint32_t meshIndex = 0; meshIndex < scene.meshes.size(); ++meshIndex) {
    const Mesh& mesh = scene.meshes[meshIndex];
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               mesh.positions.data(), 0, sizeof(Vec3), mesh.positions.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                               mesh.triangles.data(), 0, sizeof(glm::uvec3), mesh.triangles.size());
    rtcCommitGeometry(geometry);
    rtcAttachGeometryByID(rtcScene, geometry, meshIndex);
    rtcReleaseGeometry(geometry);
  }
  rtcCommitScene(rtcScene);
  bvhBytes_ = static_cast<size_t>(deviceState.bytes.load() - bytesBefore);
  throwIfEmbreeFailed(scene.sourcePath + ": building the BVH failed");
}

RayTracer::~RayTracer() = default;

std::optional<SurfaceHit> RayTracer::intersect(const Ray& ray, RayKind kind,
                                               RayCounters& counters) const {
  counters.count(kind);
  if (log_) log_->push_back({ray, false});
  if (!embreeAccepts(ray)) return std::nullopt;
  RTCRayHit rayHit;
  rayHit.ray = toEmbree(ray);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  embree::intersect1(bvh_->scene, rayHit);
  if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
  return surfaceHit(ray, rayHit.hit.geomID, rayHit.hit.primID, rayHit.ray.tfar, rayHit.hit.u,
                    rayHit.hit.v, Vec3(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z));
}

SurfaceHit RayTracer::surfaceHit(const Ray& ray, uint32_t meshIndex, uint32_t triangle, float t,
                                 float u, float v, const Vec3& frontNormal) const {
  SurfaceHit hit;
  hit.mesh = meshIndex;
  hit.triangle = triangle;
  hit.distance = t;
  const Mesh& mesh = scene_.meshes[hit.mesh];
  const glm::uvec3 tri = mesh.triangles[hit.triangle];
  // Component-wise loads: copying whole 12-byte vectors made GCC bounce them through the stack
  // with mismatched store/load sizes, which stalled every hit (measured with perf).
  const float* xyz = &mesh.positions.data()->x;
  auto vertex = [xyz](uint32_t i) { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
  const Vec3 p0 = vertex(tri.x), p1 = vertex(tri.y), p2 = vertex(tri.z);
  const float w = 1.0f - u - v;
  // The point from barycentrics lies on the triangle to float precision, unlike origin + t*dir,
  // whose error grows with the distance travelled.
  hit.position = w * p0 + u * p1 + v * p2;

  // Embree's Ng is the unnormalised front-face normal (p1 - p0) x (p2 - p0), already computed.
  const float length = glm::length(frontNormal);
  hit.frontFace = glm::dot(frontNormal, ray.direction) < 0.0f;
  if (length > 0.0f && std::isfinite(length)) {
    hit.normal = (hit.frontFace ? frontNormal : -frontNormal) * (1.0f / length);
  } else {  // a sliver too thin for a normal: face the ray
    hit.normal = -glm::normalize(ray.direction);
  }

  const Material& material = scene_.materials[mesh.material];
  hit.albedo = material.baseColor;
  if (material.baseColorTexture >= 0 && !mesh.texcoords.empty()) {
    const Vec2 uv =
        w * mesh.texcoords[tri.x] + u * mesh.texcoords[tri.y] + v * mesh.texcoords[tri.z];
    hit.albedo *= scene_.textures[material.baseColorTexture].lookup(uv);
  }
  if (material.isEmissive() && (hit.frontFace || material.doubleSided))
    hit.emitted = material.emission;
  return hit;
}

bool RayTracer::occluded(const Ray& ray, RayKind kind, RayCounters& counters) const {
  counters.count(kind);
  if (log_) log_->push_back({ray, true});
  if (!embreeAccepts(ray)) return false;
  RTCRay r = toEmbree(ray);
  embree::occluded1(bvh_->scene, r);
  return r.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
}

}  // namespace pathway

namespace pathway {
namespace {

// Embree's packet calls take a validity mask: -1 for a lane that holds a ray, 0 for one that
// does not (the lanes past `count`, and a ray Embree refuses, which then sees nothing).
void fillPacket(const Ray rays[], const uint32_t which[], int count,
                int valid[RayTracer::kPacketSize], RTCRay16& packet) {
  for (int i = 0; i < RayTracer::kPacketSize; ++i) {
    const bool used = i < count;
    const Ray& ray = rays[which[used ? i : 0]];
    valid[i] = used && embreeAccepts(ray) ? -1 : 0;
    packet.org_x[i] = ray.origin.x;
    packet.org_y[i] = ray.origin.y;
    packet.org_z[i] = ray.origin.z;
    packet.dir_x[i] = ray.direction.x;
    packet.dir_y[i] = ray.direction.y;
    packet.dir_z[i] = ray.direction.z;
    packet.tnear[i] = 0.0f;
    packet.tfar[i] = ray.tMax;
    packet.time[i] = 0.0f;
    packet.mask[i] = 0xFFFFFFFFu;
    packet.id[i] = 0;
    packet.flags[i] = 0;
  }
}

}  // namespace

void RayTracer::logQueries(const Ray rays[], const uint32_t which[], int count,
                           bool occlusionOnly) const {
  if (log_)
    for (int i = 0; i < count; ++i) log_->push_back({rays[which[i]], occlusionOnly, i == 0});
}

void RayTracer::intersectPacket(const Ray rays[], const uint32_t which[], int count, RayKind kind,
                                RayCounters& counters, std::optional<SurfaceHit> hits[]) const {
  for (int i = 0; i < count; ++i) counters.count(kind);
  logQueries(rays, which, count, false);
  alignas(64) int valid[kPacketSize];
  alignas(64) RTCRayHit16 packet;
  fillPacket(rays, which, count, valid, packet.ray);
  for (int i = 0; i < kPacketSize; ++i) {
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  embree::intersect16(valid, bvh_->scene, packet);
  for (int i = 0; i < count; ++i) {
    std::optional<SurfaceHit>& hit = hits[which[i]];
    if (packet.hit.geomID[i] == RTC_INVALID_GEOMETRY_ID) {
      hit.reset();
      continue;
    }
    hit = surfaceHit(rays[which[i]], packet.hit.geomID[i], packet.hit.primID[i], packet.ray.tfar[i],
                     packet.hit.u[i], packet.hit.v[i],
                     Vec3(packet.hit.Ng_x[i], packet.hit.Ng_y[i], packet.hit.Ng_z[i]));
  }
}

void RayTracer::occludedPacket(const Ray rays[], const uint32_t which[], int count, RayKind kind,
                               RayCounters& counters, uint8_t blocked[]) const {
  for (int i = 0; i < count; ++i) counters.count(kind);
  logQueries(rays, which, count, true);
  alignas(64) int valid[kPacketSize];
  alignas(64) RTCRay16 packet;
  fillPacket(rays, which, count, valid, packet);
  embree::occluded16(valid, bvh_->scene, packet);
  for (int i = 0; i < count; ++i) blocked[which[i]] = packet.tfar[i] < 0.0f;  // -inf on a hit
}

}  // namespace pathway
