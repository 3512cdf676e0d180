// The emitter picker's probabilities (render/emitter_picker.h): pick() chooses each emissive
// triangle by its share of the area or of the power, and pickOf() gives a bounce ray's hit
// the same triangle and probability pick() gives it, which multiple importance sampling needs.
#include "render/emitter_picker.h"

#include <gtest/gtest.h>

#include <map>

#include "test_scenes.h"

namespace pathway {
namespace {

// A floor and two emitting quads: one of side 1 and radiance 1, one of side 2 and radiance 0.5,
// so the second has 4 times the area and 2 times the power of the first.
Scene twoLights() {
  Scene scene;
  Material floor;
  floor.baseColor = Color(0.5f);
  Material dim, bright;
  dim.baseColor = bright.baseColor = Color(0.0f);
  bright.emission = Color(1.0f);
  dim.emission = Color(0.5f);
  scene.materials = {floor, bright, dim};
  test::addQuad(scene, {-5, 0, 5}, {5, 0, 5}, {5, 0, -5}, {-5, 0, -5}, 0);
  test::addQuad(scene, {0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {0, 1, 1}, 1);
  test::addQuad(scene, {-3, 1, -3}, {-1, 1, -3}, {-1, 1, -1}, {-3, 1, -1}, 2);
  test::finishScene(scene);
  return scene;
}

SurfaceHit hitOn(uint32_t mesh, uint32_t triangle) {
  SurfaceHit hit;
  hit.mesh = mesh;
  hit.triangle = triangle;
  return hit;
}

TEST(EmitterPicker, ABounceRaysHitGetsTheTriangleAndProbabilityPickGivesIt) {
  const Scene scene = twoLights();
  // Each quad is two triangles of half its area: by area 1/5 and 4/5 per quad, by power 1/3
  // and 2/3, split evenly between each quad's two triangles.
  const std::map<EmitterWeighting, std::pair<double, double>> perQuad = {
      {EmitterWeighting::Area, {0.2, 0.8}}, {EmitterWeighting::Power, {1.0 / 3.0, 2.0 / 3.0}}};
  for (const auto& [weighting, shares] : perQuad) {
    const EmitterPicker picker(scene, weighting);
    for (uint32_t triangle = 0; triangle < 2; ++triangle) {
      EXPECT_NEAR(picker.pickOf(hitOn(1, triangle)).probability, shares.first / 2.0, 1e-6);
      EXPECT_NEAR(picker.pickOf(hitOn(2, triangle)).probability, shares.second / 2.0, 1e-6);
      EXPECT_EQ(picker.pickOf(hitOn(2, triangle)).emitter->triangle, triangle);
      EXPECT_NEAR(picker.pickOf(hitOn(2, triangle)).emitter->area, 2.0f, 1e-6f);
      const EmitterPicker::Pick floor = picker.pickOf(hitOn(0, triangle));  // emits nothing
      EXPECT_EQ(floor.emitter, nullptr);
      EXPECT_EQ(floor.probability, 0.0f);
    }
    // What pick() reports for the triangle it chose agrees, over the whole range of u.
    for (float u = 0.0005f; u < 1.0f; u += 0.001f) {
      const EmitterPicker::Pick pick = picker.pick(u);
      const EmitterPicker::Pick again =
          picker.pickOf(hitOn(pick.emitter->mesh, pick.emitter->triangle));
      EXPECT_EQ(again.emitter, pick.emitter);
      EXPECT_EQ(again.probability, pick.probability);
    }
  }
}

}  // namespace
}  // namespace pathway
