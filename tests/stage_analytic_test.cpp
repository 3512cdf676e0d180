// Stages 2-5 against closed-form answers (docs/stability.md), at fixed seeds. Each statistical
// check allows kZBound = 4.5 standard errors (see render_helpers.h for the false-alarm rate); where
// a scene's finite size biases the answer, the allowance is stated next to the check.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "render/ray_budget.h"
#include "render_helpers.h"
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

Scene sceneFile(const std::string& name) {
  return loadScene(std::string(PATHWAY_SCENES_DIR) + "/" + name);
}

std::string describe(const Estimate& e) {
  return "mean " + std::to_string(e.mean) + " ± " + std::to_string(e.standardError) + " over " +
         std::to_string(e.pixels) + " pixels";
}

// ---- Ambient occlusion (stages 2 and 3) ----

TEST(StageAO, OpenPlaneIsExactlyOneAtEveryScaleAndOffset) {
  PATHWAY_REQUIRE_REFERENCE();
  for (float scale : {1e-3f, 1.0f, 1e3f}) {
    for (float offset : {0.0f, 1e4f}) {
      const Scene scene = test::openPlane(scale, offset);
      const std::string distance = std::to_string(10.0f * scale);
      for (const std::string& integrator : {test::stage(2), test::stage(3)}) {
        const RenderResult result =
            render(scene, {integrator, {{"ao-distance", distance}}, 24, 24, 8});
        // One blocked AO ray would lower a pixel by at least 1/(8·4); cos θ / (π·pdf) itself
        // rounds to 1 within a few float ulps, hence the 1e-5.
        for (const Color& pixel : result.images.color.pixels)
          ASSERT_NEAR(pixel.x, 1.0f, 1e-5)
              << integrator << " scale " << scale << " offset " << offset;
      }
    }
  }
}

TEST(StageAO, FloorUnderACeilingIsHOverRSquared) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("ceiling.gltf");  // h = 1
  // 1.02: only directions within 11.4° of the normal reach the ceiling (the grading case
  // stage3-ceiling-near-pole).
  for (double r : {1.02, 2.0, 4.0}) {
    for (const std::string& integrator : {test::stage(2), test::stage(3)}) {
      RenderSpec spec{integrator, {{"ao-distance", std::to_string(r)}}, 24, 24, 64};
      const Estimate ao = meanOverPixels(render(scene, spec));
      EXPECT_TRUE(agree(ao, (1.0 / r) * (1.0 / r)))
          << integrator << " r " << r << ": " << describe(ao);
      // Uniform instead of cosine weighting would give h/r: far outside the bound.
      EXPECT_FALSE(agree(ao, 1.0 / r)) << integrator;
    }
  }
}

TEST(StageAO, FloorBesideAWallIsOneHalfAndInACornerOneQuarter) {
  PATHWAY_REQUIRE_REFERENCE();
  // The generated walls are 200 m wide: the visible points' AO exceeds the ideal by at most
  // 0.001 (wall) and 0.0015 (corner), measured by the scene generator; that is the allowance.
  struct Case {
    const char* file;
    double expected, allowance;
  };
  for (const Case& c : {Case{"wall.gltf", 0.5, 0.001}, Case{"corner.gltf", 0.25, 0.0015}}) {
    const Scene scene = sceneFile(c.file);
    for (const std::string& integrator : {test::stage(2), test::stage(3)}) {
      const Estimate ao =
          meanOverPixels(render(scene, {integrator, {{"ao-distance", "1e6"}}, 24, 24, 64}));
      EXPECT_TRUE(agree(ao, c.expected, c.allowance))
          << c.file << " " << integrator << ": " << describe(ao);
    }
  }
}

TEST(StageAO, NestedAnd4DAgreeInMean) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("cornell_box.gltf");
  // Equal rays per pixel: nested 16 eye samples x (1 + 3 AO rays) = 64; 4D 32 samples x 2 = 64.
  const Estimate nested = meanOverPixels(
      render(scene, {test::stage(2), {{"ao-rays", "3"}, {"ao-distance", "0.2"}}, 32, 32, 16}));
  const Estimate fourD = meanOverPixels(render(
      scene, {test::stage(3), {{"ao-distance", "0.2"}}, 32, 32, 32, SamplerType::Independent, 9}));
  EXPECT_TRUE(agree(nested, fourD)) << describe(nested) << " vs " << describe(fourD);
  // ... and a different AO distance gives a clearly different mean (the test can fail).
  const Estimate shorter =
      meanOverPixels(render(scene, {test::stage(3), {{"ao-distance", "0.05"}}, 32, 32, 32}));
  EXPECT_FALSE(agree(shorter, fourD));
}

// ---- Recursive estimators in the closed furnace: albedo a = 0.5, emission Le = 1 ----

double truncatedFurnace(int depth) {
  return (1.0 - std::pow(0.5, depth + 1)) / (1.0 - 0.5);
}

TEST(StageFurnace, NaiveRecursionMatchesTheTruncatedSeriesWithExactRayCounts) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("furnace_closed.gltf");
  struct Case {
    int branching, depth;
  };
  for (const Case& c : {Case{1, 0}, Case{2, 3}, Case{3, 2}, Case{1, 6}}) {
    RenderSpec spec{
        test::stage(4),
        {{"branching", std::to_string(c.branching)}, {"depth", std::to_string(c.depth)}},
        16,
        16,
        8};
    const RenderResult result = render(scene, spec);
    const Estimate L = meanOverPixels(result);
    EXPECT_TRUE(agree(L, truncatedFurnace(c.depth)))
        << "N " << c.branching << " D " << c.depth << ": " << describe(L);
    // Every ray hits a wall in a closed room, so the count is exactly (N^(D+1) - 1) / (N - 1).
    const uint64_t samples = 16 * 16 * 8;
    const uint64_t perSample = naiveRecursionRaysPerSample(c.branching, c.depth);
    EXPECT_EQ(result.stats.counters.primary + result.stats.counters.secondary, samples * perSample);
    EXPECT_EQ(result.stats.counters.primary, samples);
  }
  EXPECT_EQ(naiveRecursionRaysPerSample(2, 3), 15u);
  EXPECT_EQ(naiveRecursionRaysPerSample(3, 2), 13u);
  EXPECT_EQ(naiveRecursionRaysPerSample(100, 2), 10101u);
  EXPECT_EQ(naiveRecursionRaysPerSample(1, 6), 7u);
  EXPECT_EQ(naiveRecursionRaysPerSample(1024, 64), UINT64_MAX);  // saturates, never wraps
}

TEST(StageFurnace, RayBudgetRefusesAnExplodingRequestBeforeRendering) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("furnace_closed.gltf");
  const IntegratorInfo& info = findIntegrator(test::stage(4));
  const ParamValues params =
      resolveParams(info.name, info.params, {{"branching", "100"}, {"depth", "4"}});
  const StageKit kit = info.kit();
  try {
    info.create({params, kit, scene});
    FAIL() << "no exception";
  } catch (const PathwayError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("101010101"), std::string::npos) << message;
    EXPECT_NE(message.find("max-rays"), std::string::npos) << message;
  }
  // Raising the budget lets the same request through.
  const ParamValues raised = resolveParams(
      info.name, info.params, {{"branching", "100"}, {"depth", "4"}, {"max-rays", "2e8"}});
  EXPECT_NO_THROW(info.create({raised, kit, scene}));
}

TEST(StageFurnace, PathTracerMatchesTruncatedAndUnlimitedSeriesWithAndWithoutNee) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("furnace_closed.gltf");
  for (const char* nee : {"0", "1"}) {
    for (int depth : {0, 1, 3}) {
      // rr-depth high: no roulette, so the truncated series is exact.
      RenderSpec spec{test::stage(5),
                      {{"max-depth", std::to_string(depth)}, {"rr-depth", "100"}, {"nee", nee}},
                      16,
                      16,
                      32};
      const Estimate L = meanOverPixels(render(scene, spec));
      EXPECT_TRUE(agree(L, truncatedFurnace(depth)))
          << "nee " << nee << " depth " << depth << ": " << describe(L);
    }
    // No depth limit, Russian roulette from the first bounce: Le / (1 - a) = 2, and it ends.
    RenderSpec spec{
        test::stage(5), {{"max-depth", "-1"}, {"rr-depth", "0"}, {"nee", nee}}, 16, 16, 64};
    const Estimate L = meanOverPixels(render(scene, spec));
    EXPECT_TRUE(agree(L, 2.0)) << "nee " << nee << ": " << describe(L);
    EXPECT_FALSE(agree(L, truncatedFurnace(3)));  // not just a truncated sum
  }
}

// A closed room of albedo 1 reflects everything: only Russian roulette ends a path there. The
// depth cap is far out of reach (0.95^1000 ≈ 5e-23), so it only guards against a hang.
TEST(StageFurnace, RouletteAloneEndsPathsInAClosedWhiteRoom) {
  PATHWAY_REQUIRE_REFERENCE();
  Scene scene = sceneFile("furnace_closed.gltf");
  for (Material& material : scene.materials) {
    material.baseColor = Color(1.0f);
    material.emission = Color(0.0f);  // nothing emits: the answer is 0 and no NEE ray is cast
  }
  const int width = 16, height = 16, spp = 16;
  const RenderResult result = render(scene, {test::stage(5),
                                             {{"max-depth", "1000"}, {"rr-depth", "0"}},
                                             width,
                                             height,
                                             static_cast<uint32_t>(spp)});
  EXPECT_EQ(meanOverPixels(result).mean, 0.0);
  const double samples = double(width) * height * spp;
  const double bouncesPerPath = result.stats.counters.secondary / samples;
  EXPECT_LT(bouncesPerPath, 100.0) << "paths are not ended by roulette";
  if (!test::checkingStudentCode()) {
    // The reference survives with q = min(0.95, max throughput) = 0.95 here: the number of
    // bounce rays is geometric, mean q/(1-q) = 19, variance q/(1-q)^2 = 380.
    const double standardError = std::sqrt(380.0 / samples);
    EXPECT_NEAR(bouncesPerPath, 19.0, test::kZBound * standardError);
  }
}

TEST(StageFurnace, WhiteFurnaceIsOneEverywhereAndTerminatesAtAlbedoOne) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = sceneFile("white_furnace.gltf");
  for (const char* nee : {"0", "1"}) {
    // Albedo 1, no depth cap: only Russian roulette (q < 1) or escaping ends a path.
    RenderSpec spec{
        test::stage(5), {{"max-depth", "-1"}, {"rr-depth", "0"}, {"nee", nee}}, 24, 24, 32};
    const RenderResult result = render(scene, spec);
    const Estimate L = meanOverPixels(result);
    EXPECT_TRUE(agree(L, 1.0)) << "nee " << nee << ": " << describe(L);
    EXPECT_EQ(result.stats.counters.invalidSamples, 0u);
  }
}

// Stage 5's default sampler is Owen-scrambled Sobol'. Its points are not independent, so this
// checks that they still average to the right answer: the furnace series (the pixels' own
// variance over-states Sobol's error, which only makes the check conservative) and, on the
// Cornell box, the mean of an independent render.
TEST(StageFurnace, PathTracerWithSobolMatchesTheSeriesAndIndependentSampling) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene furnace = sceneFile("furnace_closed.gltf");
  for (int depth : {1, 3, -1}) {
    RenderSpec spec{
        test::stage(5), {{"max-depth", std::to_string(depth)}, {"rr-depth", "0"}}, 16, 16, 32};
    spec.sampler = SamplerType::Sobol;
    const Estimate L = meanOverPixels(render(furnace, spec));
    EXPECT_TRUE(agree(L, depth < 0 ? 2.0 : truncatedFurnace(depth)))
        << "depth " << depth << ": " << describe(L);
  }
  const Scene box = sceneFile("cornell_box.gltf");
  RenderSpec sobol{test::stage(5), {}, 48, 48, 16};
  sobol.sampler = SamplerType::Sobol;
  RenderSpec independent = sobol;
  independent.sampler = SamplerType::Independent;
  independent.seed = 2;
  const RenderResult withSobol = render(box, sobol), withIndependent = render(box, independent);
  for (int channel = 0; channel < 3; ++channel) {
    const Estimate a = meanOverPixels(withSobol, channel);
    const Estimate b = meanOverPixels(withIndependent, channel);
    EXPECT_TRUE(agree(a, b)) << "channel " << channel << ": Sobol' " << describe(a)
                             << ", independent " << describe(b);
  }
}

}  // namespace
}  // namespace pathway
