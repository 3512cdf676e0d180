// Stability where methods fail (docs/stability.md): shrinking lights, lights touching walls,
// degenerate emitters, grazing rays. Outputs must stay finite and non-negative, bad samples are
// counted, and means stay right. Statistical checks use kZBound (render_helpers.h).
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "render_helpers.h"
#include "scene/emitters.h"
#include "scene/gltf_loader.h"
#include "stage_under_test.h"
#include "test_scenes.h"

namespace pathway {
namespace {

using test::agree;
using test::Estimate;
using test::meanOverPixels;
using test::render;
using test::RenderSpec;

void expectFiniteAndNonNegative(const RenderResult& result, const std::string& what) {
  EXPECT_EQ(result.stats.counters.invalidSamples, 0u) << what;
  for (const Color& pixel : result.images.color.pixels) {
    ASSERT_TRUE(isFinite(pixel)) << what;
    ASSERT_GE(std::fmin(pixel.x, std::fmin(pixel.y, pixel.z)), 0.0f) << what;
  }
}

// Per-sample relative variance over the central pixels: var(sample) / mean², with the box filter
// var(sample) = spp · var(pixel mean).
double relativeVariance(const RenderResult& result, uint32_t spp) {
  const Image& color = result.images.color;
  double sumMean = 0.0, sumVariance = 0.0;
  int count = 0;
  for (int y = color.height / 4; y < 3 * color.height / 4; ++y)
    for (int x = color.width / 4; x < 3 * color.width / 4; ++x) {
      sumMean += color.at(x, y).x;
      sumVariance += result.images.variance.at(x, y).x * spp;
      ++count;
    }
  const double mean = sumMean / count;
  return (sumVariance / count) / (mean * mean);
}

TEST(StageStability, ShrinkingLightAtFixedPowerNeedsNextEventEstimation) {
  PATHWAY_REQUIRE_REFERENCE();
  const uint32_t spp = 64;
  double relVarNoNee[3], relVarNee[3];
  const float sides[3] = {0.4f, 0.1f, 0.025f};  // areas 256 : 16 : 1
  for (int i = 0; i < 3; ++i) {
    const Scene scene = test::smallLight(sides[i]);
    auto spec = [&](const char* nee) {
      return RenderSpec{test::stage(5), {{"max-depth", "1"}, {"nee", nee}}, 33, 33, spp};
    };
    const RenderResult withNee = render(scene, spec("1"));
    const RenderResult withoutNee = render(scene, spec("0"));
    expectFiniteAndNonNegative(withNee, "nee");
    expectFiniteAndNonNegative(withoutNee, "no nee");
    relVarNee[i] = relativeVariance(withNee, spp);
    relVarNoNee[i] = relativeVariance(withoutNee, spp);
    // Means agree while the light is large enough for bounce rays to find it often; at the
    // smallest size the no-NEE estimate has too few light hits for its own error bar to be honest.
    if (i < 2) {
      EXPECT_TRUE(agree(meanOverPixels(withNee), meanOverPixels(withoutNee)))
          << "side " << sides[i];
    }
  }
  // Without NEE the relative variance grows like 1/area (x256 here; we ask for x30), with NEE it
  // stays flat (we allow x2).
  EXPECT_GT(relVarNoNee[2] / relVarNoNee[0], 30.0)
      << relVarNoNee[0] << " " << relVarNoNee[1] << " " << relVarNoNee[2];
  EXPECT_LT(relVarNee[2] / relVarNee[0], 2.0) << relVarNee[0] << " " << relVarNee[2];
}

TEST(StageStability, SmallLightCentreMatchesTheFormFactor) {
  PATHWAY_REQUIRE_REFERENCE();
  // Radiance of the floor right below a square light of side s at height 1 with power 1:
  // L = ρ/π · E, E = Φ/(π s²) · π · F, F = 4 · (1/2π) · 2 · (a/r) · atan(a/r), a = s/2, r =
  // √(1+a²).
  const double side = 0.1, a = 0.5 * side, r = std::sqrt(1.0 + a * a);
  const double F = 4.0 * (1.0 / (2.0 * M_PI)) * 2.0 * (a / r) * std::atan(a / r);
  const double expected = 0.5 / M_PI * (1.0 / (M_PI * side * side)) * M_PI * F;
  const RenderResult result =
      render(test::smallLight(side), {test::stage(5), {{"max-depth", "1"}}, 33, 33, 1024});
  const Estimate centre =
      meanOverPixels(result, 0, [](int x, int y) { return x == 16 && y == 16; });
  // The centre pixel sees ±4.5 cm of floor along the view (the camera looks down at 22°), where
  // L ∝ (1 + d²)^-2 falls by up to 0.4 %; the pixel's average sits about 0.14 % under the centre
  // value. Allowance 0.3 %: a wrong factor anywhere in the estimator is far larger.
  EXPECT_TRUE(agree(centre, expected, 0.003 * expected))
      << centre.mean << " ± " << centre.standardError << " vs " << expected;
}

TEST(StageStability, LightTouchingAWallStaysFiniteAndUnbiased) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/light_touching_wall.gltf");
  const RenderResult nee = render(scene, {test::stage(5), {{"max-depth", "3"}}, 32, 32, 64});
  const RenderResult noNee = render(scene, {test::stage(5),
                                            {{"max-depth", "3"}, {"nee", "0"}},
                                            32,
                                            32,
                                            64,
                                            SamplerType::Independent,
                                            2});
  expectFiniteAndNonNegative(nee, "nee");
  expectFiniteAndNonNegative(noNee, "no nee");
  EXPECT_TRUE(agree(meanOverPixels(nee), meanOverPixels(noNee)));
}

TEST(StageStability, NeeOnAndOffAgreeOnTheCornellBox) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf");
  for (int channel = 0; channel < 3; ++channel) {
    const RenderResult nee = render(scene, {test::stage(5), {{"max-depth", "3"}}, 24, 24, 64});
    const RenderResult noNee =
        render(scene, {test::stage(5), {{"max-depth", "3"}, {"nee", "0"}}, 24, 24, 256});
    EXPECT_TRUE(agree(meanOverPixels(nee, channel), meanOverPixels(noNee, channel))) << channel;
  }
}

// A box room plus emitters that cannot emit: a zero-area (collinear) triangle and a sliver.
Scene roomWithDegenerateEmitters() {
  Scene scene = test::boxRoom();
  Mesh mesh;
  mesh.name = "degenerate emitters";
  mesh.positions = {{0, 0.5f, 0}, {0.1f, 0.5f, 0}, {0.2f, 0.5f, 0},  // collinear: zero area
                    {0, 0.4f, 0}, {0, 0.4f, 0},    {0, 0.4f, 0}};    // one point three times
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  mesh.material = 2;  // the emissive material
  scene.meshes.push_back(std::move(mesh));
  test::finishScene(scene);
  return scene;
}

TEST(StageStability, DegenerateAndZeroAreaEmittersAreSkipped) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene clean = test::boxRoom();
  const Scene dirty = roomWithDegenerateEmitters();
  EXPECT_EQ(collectEmissiveTriangles(dirty).size(), collectEmissiveTriangles(clean).size());
  for (const char* pick : {"area", "power"}) {
    const RenderSpec spec{test::stage(5), {{"light-pick", pick}}, 24, 24, 32};
    const RenderResult a = render(clean, spec), b = render(dirty, spec);
    expectFiniteAndNonNegative(b, std::string("light-pick ") + pick);
    // Same lights, same random numbers: the degenerate ones change nothing at all.
    EXPECT_EQ(meanOverPixels(a).mean, meanOverPixels(b).mean) << pick;
  }
}

TEST(StageStability, GrazingCameraRaysStayFiniteInEveryStage) {
  PATHWAY_REQUIRE_REFERENCE();
  Scene scene = test::boxRoom();
  // Eye exactly in the floor plane, looking along it: rays graze the floor.
  scene.camera->cameraToWorld =
      glm::inverse(glm::lookAt(Vec3(0.0f, -1.0f, 0.9f), Vec3(0.0f, -1.0f, -1.0f), Vec3(0, 1, 0)));
  for (int stage = 1; stage <= 5; ++stage) {
    const std::string integrator = test::stage(stage);
    expectFiniteAndNonNegative(render(scene, {integrator, {}, 24, 24, 8}), integrator);
  }
}

// ---- Skeletons: they run, stay finite, and say which file to open. ----

TEST(StageSkeletons, StudentSkeletonsRunAndReportTheirTodos) {
  // In a handout, assignments/ holds the student's own work, finished or not.
  if (!test::kFullRepository) GTEST_SKIP() << "needs the untouched skeletons";
  const Scene scene = test::boxRoom();
  for (int stage = 1; stage <= 5; ++stage) {
    const std::string name = "stage" + std::to_string(stage);
    const RenderResult student = render(scene, {name, {}, 16, 16, 2});
    expectFiniteAndNonNegative(student, name);
    bool namesItsFile = false;
    for (const TodoRecord& todo : student.todos)
      namesItsFile |= todo.file.find("assignments/stage" + std::to_string(stage) + "/") == 0;
    // Stage 1's TODOs sit in the splat, which every stage calls; a later stage's own file must
    // appear too.
    EXPECT_TRUE(namesItsFile) << name << " ran no TODO of its own file";
  }
}

TEST(StageSkeletons, ReferenceSolutionsHaveNoTodos) {
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages";
  const Scene scene = test::boxRoom();
  for (int stage = 1; stage <= 5; ++stage) {
    const std::string name = "stage" + std::to_string(stage) + "@ref";
    EXPECT_TRUE(render(scene, {name, {}, 16, 16, 2}).todos.empty()) << name;
  }
}

}  // namespace
}  // namespace pathway
