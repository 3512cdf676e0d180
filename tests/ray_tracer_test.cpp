// Ray queries: counters, front/back faces, no self-intersection at any scale or offset, and rays
// aimed at shared edges and vertices (robust traversal).
#include "scene/ray_tracer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>
#include <vector>

#include "sampling/pcg32.h"
#include "scene/camera.h"
#include "scene/embree.h"
#include "test_scenes.h"

namespace pathway {
namespace {

// Cosine-distributed direction around +y (Malley's method), written out here so the test does not
// lean on any stage's code.
Vec3 cosineAroundUp(float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  return Vec3(r * std::cos(phi), std::sqrt(std::fmax(0.0f, 1.0f - u1)), r * std::sin(phi));
}

TEST(RayTracer, OpenPlaneHasNoSelfIntersectionAtAnyScaleOrOffset) {
  for (float scale : {1e-3f, 1e-2f, 1e-1f, 1.0f, 1e1f, 1e2f, 1e3f}) {
    for (float offset : {0.0f, 1e4f, -1e4f}) {
      const Scene scene = test::openPlane(scale, offset);
      const RayTracer tracer(scene);
      const Camera camera(scene, 64, 64);
      RayCounters counters;
      Pcg32 rng(42);
      int hits = 0, blocked = 0;
      for (int i = 0; i < 4000; ++i) {
        const Vec2 film(64.0f * rng.nextFloat(), 32.0f + 32.0f * rng.nextFloat());
        const auto hit = tracer.intersect(camera.generateRay(film), RayKind::Primary, counters);
        if (!hit) continue;
        ++hits;
        const Vec3 direction = cosineAroundUp(rng.nextFloat(), rng.nextFloat());
        // Both query kinds, with an unbounded and with an AO-like bounded segment.
        const Ray ray = hit->spawnRay(direction);
        const Ray shortRay = hit->spawnRay(direction, 0.5f * scale);
        if (tracer.occluded(ray, RayKind::Shadow, counters) ||
            tracer.occluded(shortRay, RayKind::Secondary, counters) ||
            tracer.intersect(ray, RayKind::Secondary, counters))
          ++blocked;
      }
      EXPECT_GT(hits, 3000) << "scale " << scale << " offset " << offset;
      EXPECT_EQ(blocked, 0) << "scale " << scale << " offset " << offset;  // AO is exactly 1
      EXPECT_EQ(counters.primary, 4000u);
      EXPECT_EQ(counters.secondary, 2u * hits);
      EXPECT_EQ(counters.shadow, static_cast<uint64_t>(hits));
    }
  }
}

// Watertightness: a ray aimed exactly at a shared edge must hit one of the two triangles there,
// not slip between them. A tilted, jittered grid of triangles (no coordinate aligned with an
// axis), rays from random points above it aimed at random points on its inner edges and at its
// inner vertices. Measured with this test (and once with RTC_SCENE_FLAG_NONE in bvhFlags): without
// Embree's robust mode 5.3 % of the edge rays and 17 % of the vertex rays miss (in a closed room,
// light would leak through every seam); with it no edge ray misses, and 0.2 % of the vertex rays
// still do: Embree 3's robust test is not watertight exactly at a vertex (misses there are a known
// report, embree issue #387). A random ray meets a vertex with probability zero, so only rays
// aimed at vertices see it. Embree picks its kernels by processor, hence the margin of 1 %.
TEST(RayTracer, RaysAimedAtSharedEdgesAlwaysHitAndAtVerticesNearlyAlways) {
  constexpr int kCells = 16;
  Scene scene;
  scene.sourcePath = "jittered grid (test)";
  Mesh mesh;
  mesh.name = "grid";
  Pcg32 rng(7);
  const glm::mat3 tilt =
      glm::mat3(glm::rotate(glm::mat4(1.0f), 0.37f, glm::normalize(Vec3(1, 2, 3))));
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) {
      const bool border = i == 0 || j == 0 || i == kCells || j == kCells;
      // One draw per statement: the order of a call's arguments is up to the compiler.
      Vec2 jitter(0.0f);
      if (!border) {
        jitter.x = rng.nextFloat() - 0.5f;
        jitter.y = rng.nextFloat() - 0.5f;
      }
      mesh.positions.push_back(tilt *
                               Vec3(float(i) + 0.4f * jitter.x, 0.0f, float(j) + 0.4f * jitter.y));
    }
  auto vertex = [](int i, int j) { return static_cast<uint32_t>(j * (kCells + 1) + i); };
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      mesh.triangles.emplace_back(vertex(i, j), vertex(i, j + 1), vertex(i + 1, j + 1));
      mesh.triangles.emplace_back(vertex(i, j), vertex(i + 1, j + 1), vertex(i + 1, j));
    }
  // Inner edges (each shared by two triangles) as vertex pairs: along i, along j, diagonal.
  std::vector<std::pair<uint32_t, uint32_t>> innerEdges;
  for (int j = 1; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) innerEdges.emplace_back(vertex(i, j), vertex(i + 1, j));
  for (int j = 0; j < kCells; ++j)
    for (int i = 1; i < kCells; ++i) innerEdges.emplace_back(vertex(i, j), vertex(i, j + 1));
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) innerEdges.emplace_back(vertex(i, j), vertex(i + 1, j + 1));
  scene.meshes.push_back(mesh);
  test::finishScene(scene);
  const RayTracer tracer(scene);

  const Vec3 up = tilt * Vec3(0, 1, 0);
  RayCounters counters;
  auto hits = [&](const Vec3& target) {
    const float x = kCells * rng.nextFloat(), z = kCells * rng.nextFloat();
    const float height = 0.5f + 4.0f * rng.nextFloat();
    const Vec3 origin = tilt * Vec3(x, 0.0f, z) + height * up;
    const Ray ray{origin, glm::normalize(target - origin)};
    return tracer.intersect(ray, RayKind::Primary, counters).has_value();
  };
  int edgeRays = 0, edgeMisses = 0, vertexRays = 0, vertexMisses = 0;
  for (int round = 0; round < 40; ++round) {
    for (const auto& [a, b] : innerEdges) {
      const float t = rng.nextFloat();
      ++edgeRays;
      if (!hits(mesh.positions[a] + t * (mesh.positions[b] - mesh.positions[a]))) ++edgeMisses;
    }
    for (int j = 1; j < kCells; ++j)
      for (int i = 1; i < kCells; ++i) {
        ++vertexRays;
        if (!hits(mesh.positions[vertex(i, j)])) ++vertexMisses;
      }
  }
  EXPECT_EQ(edgeMisses, 0) << "of " << edgeRays << " rays aimed at shared edges";
  EXPECT_LT(vertexMisses, vertexRays / 100) << "of " << vertexRays << " rays aimed at vertices";
}

TEST(RayTracer, ReportsFaceSideNormalAlbedoAndOneSidedEmission) {
  Scene scene;
  Material light;
  light.baseColor = Color(0.25f, 0.5f, 0.75f);
  light.emission = Color(3.0f);
  scene.materials = {light};
  // A quad at y = 0 facing +y.
  test::addQuad(scene, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, 0);
  test::finishScene(scene);
  const RayTracer tracer(scene);
  RayCounters counters;

  const auto front =
      tracer.intersect({Vec3(0.2f, 2, 0.1f), Vec3(0, -1, 0)}, RayKind::Primary, counters);
  ASSERT_TRUE(front);
  EXPECT_TRUE(front->frontFace);
  EXPECT_NEAR(front->distance, 2.0f, 1e-6);
  EXPECT_NEAR(glm::distance(front->position, Vec3(0.2f, 0, 0.1f)), 0.0f, 1e-6);
  EXPECT_NEAR(glm::distance(front->normal, Vec3(0, 1, 0)), 0.0f, 1e-6);
  EXPECT_EQ(front->albedo, light.baseColor);
  EXPECT_EQ(front->emitted, Color(3.0f));

  const auto back =
      tracer.intersect({Vec3(0.2f, -2, 0.1f), Vec3(0, 1, 0)}, RayKind::Primary, counters);
  ASSERT_TRUE(back);
  EXPECT_FALSE(back->frontFace);
  EXPECT_NEAR(glm::distance(back->normal, Vec3(0, -1, 0)), 0.0f, 1e-6);  // faces the ray
  EXPECT_EQ(back->emitted, Color(0.0f));  // one-sided emitter seen from behind

  scene.materials[0].doubleSided = true;
  const auto backDouble =
      tracer.intersect({Vec3(0.2f, -2, 0.1f), Vec3(0, 1, 0)}, RayKind::Primary, counters);
  ASSERT_TRUE(backDouble);
  EXPECT_EQ(backDouble->emitted, Color(3.0f));

  // Segments: tMax stops short of the quad; an occlusion query agrees with intersect.
  EXPECT_FALSE(
      tracer.intersect({Vec3(0, 2, 0), Vec3(0, -1, 0), 1.9f}, RayKind::Secondary, counters));
  EXPECT_FALSE(tracer.occluded({Vec3(0, 2, 0), Vec3(0, -1, 0), 1.9f}, RayKind::Shadow, counters));
  EXPECT_TRUE(tracer.occluded({Vec3(0, 2, 0), Vec3(0, -1, 0), 2.1f}, RayKind::Shadow, counters));
}

TEST(RayTracer, ShadowRayToALightPointIsNotBlockedByEitherEnd) {
  Scene scene;
  scene.materials = {Material{}};
  test::addQuad(scene, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, 0);  // floor, up
  test::addQuad(scene, {-1, 1, -1}, {1, 1, -1}, {1, 1, 1}, {-1, 1, 1}, 0);  // ceiling, down
  test::finishScene(scene);
  const RayTracer tracer(scene);
  RayCounters counters;
  Pcg32 rng(3);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 down(2 * rng.nextFloat() - 1, -1.5f, 2 * rng.nextFloat() - 1);  // stays on the floor
    const auto hit = tracer.intersect({Vec3(0, 0.5f, 0), down}, RayKind::Primary, counters);
    ASSERT_TRUE(hit);
    const Vec3 target(2 * rng.nextFloat() - 1, 1, 2 * rng.nextFloat() - 1);
    const Ray shadow = hit->spawnRayTo(target, Vec3(0, -1, 0));
    EXPECT_FALSE(tracer.occluded(shadow, RayKind::Shadow, counters)) << i;
    // The same segment pushed past the target does hit the ceiling: the test can fail.
    Ray tooLong = shadow;
    tooLong.tMax = 1.01f;
    EXPECT_TRUE(tracer.occluded(tooLong, RayKind::Shadow, counters)) << i;
  }
}

TEST(RayTracer, ARayEmbreeRefusesSeesNothingAndIsCounted) {
  // A NaN direction (a frame built on a zero vector) or an infinite origin: Embree's debug builds
  // abort on such a ray; the tracer answers "nothing there" and the NaN goes on to the image.
  Scene scene;
  scene.materials = {Material{}};
  test::addQuad(scene, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, 0);  // floor, up
  test::finishScene(scene);
  const RayTracer tracer(scene);
  RayCounters counters;
  const float nan = std::nanf(""), inf = kInfinity;
  for (const Ray& ray :
       {Ray{Vec3(0, 1, 0), Vec3(nan, -1, 0)}, Ray{Vec3(0, 1, 0), Vec3(0, nan, 0)},
        Ray{Vec3(0, inf, 0), Vec3(0, -1, 0)}, Ray{Vec3(0, 1, 0), Vec3(0, -1, 0), nan}}) {
    EXPECT_FALSE(tracer.intersect(ray, RayKind::Primary, counters));
    EXPECT_FALSE(tracer.occluded(ray, RayKind::Shadow, counters));
  }
  EXPECT_EQ(counters.totalRays(), 8u);
  // The same ray with finite numbers hits the floor: the test can fail.
  EXPECT_TRUE(tracer.intersect({Vec3(0, 1, 0), Vec3(0, -1, 0)}, RayKind::Primary, counters));
  // Embree's limits: coordinates up to about 1.8e18, any length but NaN.
  EXPECT_TRUE(embreeAccepts({Vec3(1.8e18f, 0, 0), Vec3(0, -1, 0)}));
  EXPECT_FALSE(embreeAccepts({Vec3(1.9e18f, 0, 0), Vec3(0, -1, 0)}));
  EXPECT_FALSE(embreeAccepts({Vec3(0, 1, 0), Vec3(0, -1.9e18f, 0)}));
  EXPECT_TRUE(embreeAccepts({Vec3(0, 1, 0), Vec3(0, -1, 0), kInfinity}));
  // A packet answers a refused ray as the single-ray query does, and its other rays as usual.
  const Ray packet[] = {{Vec3(0, 1, 0), Vec3(nan, -1, 0)}, {Vec3(0, 1, 0), Vec3(0, -1, 0)}};
  const uint32_t which[] = {0, 1};
  std::optional<SurfaceHit> hits[2];
  uint8_t blocked[2] = {1, 0};
  tracer.intersectPacket(packet, which, 2, RayKind::Primary, counters, hits);
  tracer.occludedPacket(packet, which, 2, RayKind::Shadow, counters, blocked);
  EXPECT_FALSE(hits[0]);
  EXPECT_TRUE(hits[1]);
  EXPECT_FALSE(blocked[0]);
  EXPECT_TRUE(blocked[1]);
}

// Every scene is traced robustly; only large ones trade speed for compact memory.
TEST(RayTracer, BvhIsRobustAlwaysAndCompactOnlyForLargeScenes) {
  EXPECT_EQ(bvhFlags(32), RTC_SCENE_FLAG_ROBUST);
  EXPECT_EQ(bvhFlags(kCompactBvhFromTriangles - 1), RTC_SCENE_FLAG_ROBUST);
  EXPECT_EQ(bvhFlags(kCompactBvhFromTriangles), RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
}

}  // namespace
}  // namespace pathway
