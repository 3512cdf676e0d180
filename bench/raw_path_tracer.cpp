#include "raw_path_tracer.h"

#include <tbb/blocked_range.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>

#include <cmath>

#include "sampling/hash.h"
#include "sampling/pcg32.h"
#include "sampling/sampler.h"

namespace pathway::bench {
namespace {

// Rows per parallel task. A row of 256 pixels at 64 spp is already thousands of paths, so a few
// rows make the task overhead invisible and still leave dozens of tasks to balance the cores.
constexpr int kRowsPerTile = 4;

RTCRay embreeRay(const Vec3& origin, const Vec3& direction, float tMax) {
  RTCRay r;
  r.org_x = origin.x, r.org_y = origin.y, r.org_z = origin.z;
  r.dir_x = direction.x, r.dir_y = direction.y, r.dir_z = direction.z;
  r.tnear = 0.0f, r.tfar = tMax, r.time = 0.0f;
  r.mask = 0xFFFFFFFFu, r.id = 0, r.flags = 0;
  return r;
}

// One PCG32 per pixel, seeded from (pixel, seed), with SampleStream's two calls.
struct PcgNumbers {
  Pcg32 rng;
  float next1D() { return rng.nextFloat(); }
  Vec2 next2D() {
    const float u = rng.nextFloat();
    return Vec2(u, rng.nextFloat());
  }
};

}  // namespace

RawPathTracer::RawPathTracer(const Scene& scene, const RawEmbree& embree)
    : scene_(scene), embree_(embree.handle()), lights_(scene, EmitterWeighting::Area) {
  for (const Mesh& mesh : scene.meshes) {
    const Material& material = scene.materials[mesh.material];
    meshes_.push_back({material.baseColor, material.isEmissive() ? material.emission : Color(0.0f),
                       material.doubleSided});
  }
}

RawPathImage RawPathTracer::render(const Camera& camera, const RawPathSettings& settings) const {
  RawPathImage image;
  image.width = settings.width;
  image.height = settings.height;
  image.pixels.assign(static_cast<size_t>(settings.width) * settings.height, Color(0.0f));
  tbb::combinable<RayCounters> threadRays;
  const Sampler sobol(SamplerType::Sobol, settings.samplesPerPixel, settings.seed);
  // Box filter one pixel wide: a uniform point in the pixel, weight 1, own pixel only.
  auto sample = [&](int x, int y, auto& numbers, RayCounters& rays) {
    const Ray ray = camera.generateRay(Vec2(x, y) + numbers.next2D());
    return radiance(ray, settings, numbers, rays);
  };
  auto renderRows = [&](const tbb::blocked_range<int>& rows) {
    RayCounters rays;  // this tile's, added to the thread's total once at its end
    for (int y = rows.begin(); y < rows.end(); ++y) {
      for (int x = 0; x < settings.width; ++x) {
        const size_t pixel = static_cast<size_t>(y) * settings.width + x;
        Color sum(0.0f);
        if (settings.sobol) {
          const uint64_t pixelKey = sobol.pixelKey(x, y);
          for (uint32_t i = 0; i < settings.samplesPerPixel; ++i) {
            SampleStream numbers(sobol, pixelKey, i);
            sum += sample(x, y, numbers, rays);
          }
        } else {
          // One generator per pixel, seeded from (pixel, seed): the image does not depend on
          // which thread rendered which rows.
          PcgNumbers numbers{Pcg32(hashValues(pixel, settings.seed))};
          for (uint32_t i = 0; i < settings.samplesPerPixel; ++i)
            sum += sample(x, y, numbers, rays);
        }
        image.pixels[pixel] = sum / static_cast<float>(settings.samplesPerPixel);
      }
    }
    rays.samples = static_cast<uint64_t>(rows.size()) * settings.width * settings.samplesPerPixel;
    threadRays.local() += rays;
  };
  tbb::parallel_for(tbb::blocked_range<int>(0, settings.height, kRowsPerTile), renderRows);
  threadRays.combine_each([&](const RayCounters& rays) { image.rays += rays; });
  return image;
}

// Stage 5's estimator, step for step (solutions/stage5/stage5_path_tracing.cpp), with the
// algebra an expert would fold: BRDF · cos / pdf of a cosine-weighted direction is the albedo.
template <typename Numbers>
Color RawPathTracer::radiance(const Ray& cameraRay, const RawPathSettings& settings,
                              Numbers& numbers, RayCounters& rays) const {
  Color result(0.0f);
  Color throughput(1.0f);
  Vec3 origin = cameraRay.origin;
  Vec3 direction = cameraRay.direction;

  for (int bounce = 0;; ++bounce) {
    RTCRayHit rayHit;
    rayHit.ray = embreeRay(origin, direction, kInfinity);
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    embree::intersect1(embree_, rayHit);
    ++(bounce == 0 ? rays.primary : rays.secondary);
    if (rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID) {
      result += throughput * scene_.background;  // NEE never samples the background
      break;
    }

    const MeshShading& shading = meshes_[rayHit.hit.geomID];
    // Embree's Ng is the unnormalised front-face normal (v1 - v0) x (v2 - v0), as the scene's
    // counter-clockwise winding defines the front: no need to fetch the vertices for it.
    const Vec3 ng(rayHit.hit.Ng_x, rayHit.hit.Ng_y, rayHit.hit.Ng_z);
    const bool frontFace = glm::dot(ng, direction) < 0.0f;
    // With NEE, emitters found by bounces are already counted by the shadow rays: camera only.
    if (bounce == 0 && (frontFace || shading.doubleSided)) result += shading.emission;
    if (settings.maxDepth >= 0 && bounce >= settings.maxDepth) break;

    const Vec3 normal = glm::normalize(frontFace ? ng : -ng);  // facing the incoming ray
    // The point from barycentrics lies on the triangle to float precision, which the few-ULP
    // origin offset relies on; origin + t · direction drifts with the distance travelled.
    const Mesh& mesh = scene_.meshes[rayHit.hit.geomID];
    const glm::uvec3 triangle = mesh.triangles[rayHit.hit.primID];
    const float* xyz = &mesh.positions.data()->x;  // component loads: no 12-byte copies
    auto vertex = [xyz](uint32_t i) { return Vec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]); };
    const float u = rayHit.hit.u, v = rayHit.hit.v;
    const Vec3 position =
        (1.0f - u - v) * vertex(triangle.x) + u * vertex(triangle.y) + v * vertex(triangle.z);
    // Every ray leaving this point goes into the hemisphere of `normal`, so one offset serves all.
    const Vec3 leaving = offsetRayOrigin(position, normal);

    result += throughput * directLight(position, leaving, normal, shading.albedo, numbers, rays);

    // One cosine-weighted continuation: BRDF · cos / pdf = (albedo / π) · cos / (cos / π).
    const Vec2 uDirection = numbers.next2D();
    const float r = std::sqrt(uDirection.x), phi = 2.0f * kPi * uDirection.y;
    const Vec3 local(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0f - uDirection.x));
    throughput *= shading.albedo;

    if (bounce + 1 >= settings.rouletteDepth) {
      // As stage 5: survive with q = min(0.95, max throughput), divide by q.
      const float q = std::fmin(0.95f, maxComponent(throughput));
      if (numbers.next1D() >= q) break;
      throughput /= q;
    }
    origin = leaving;
    direction = Frame(normal).toWorld(local);
  }
  return result;
}

// Next-event estimation: one shadow ray to a uniform point on an emitter picked by area.
template <typename Numbers>
Color RawPathTracer::directLight(const Vec3& position, const Vec3& leaving, const Vec3& normal,
                                 const Color& albedo, Numbers& numbers, RayCounters& rays) const {
  const float uPick = numbers.next1D();
  const Vec2 uPoint = numbers.next2D();
  if (lights_.empty()) return Color(0.0f);
  const EmitterPicker::Pick pick = lights_.pick(uPick);
  const EmissiveTriangle& light = *pick.emitter;
  const float s = std::sqrt(uPoint.x);  // uniform on the triangle: density 1 / area
  const float b0 = 1.0f - s, b1 = uPoint.y * s;
  const Vec3 target = b0 * light.p0 + b1 * light.p1 + (1.0f - b0 - b1) * light.p2;

  const Vec3 toLight = target - position;
  const float distanceSquared = glm::dot(toLight, toLight);
  if (!(distanceSquared > 0.0f)) return Color(0.0f);
  const Vec3 wi = toLight / std::sqrt(distanceSquared);
  const float cosSurface = glm::dot(normal, wi);
  const float cosLight = -glm::dot(light.normal, wi);
  // A one-sided emitter lights only the side its front face looks at.
  if (cosSurface <= 0.0f || cosLight == 0.0f || (cosLight < 0.0f && !light.doubleSided))
    return Color(0.0f);

  // The far end moves off the emitter towards the surface: the segment (0, 1] stops just short
  // of the emitter, so the emitter itself cannot block it.
  const Vec3 end = offsetRayOrigin(target, cosLight > 0.0f ? light.normal : -light.normal);
  RTCRay shadow = embreeRay(leaving, end - leaving, 1.0f);
  embree::occluded1(embree_, shadow);
  ++rays.shadow;
  if (shadow.tfar < 0.0f) return Color(0.0f);  // Embree sets tfar to -inf when blocked
  // L_e · (albedo / π) · cos θ_x · |cos θ_y| / d² / p_A, with p_A = P(triangle) / area.
  const float geometry = cosSurface * std::fabs(cosLight) / distanceSquared;
  return light.emission * albedo * (kInvPi * geometry * light.area / pick.probability);
}

}  // namespace pathway::bench
