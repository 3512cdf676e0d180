// Each lecture demo makes its point, in numbers: the demo as declared (viewer_demos.cpp) is run
// through the viewer's own machinery (its state, job, render worker and reference maker) at a
// small size, and the number the lecturer points at is checked with a margin.
//
// Fixed seeds make every figure deterministic. The margins are stated beside each check; they
// were measured over seeds 1-10 (PATHWAY_DEMO_POINT_SEEDS=10 runs them all and prints each
// figure: docs/slides.md, "Each demo's point is a test").
#ifdef PATHWAY_HAS_VIEWER

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

#include "chart/image_error.h"
#include "render/integrator_registry.h"
#include "viewer/initial_state.h"
#include "viewer/reference_maker.h"
#include "viewer/render_worker.h"
#include "viewer/viewer_demos.h"
#include "viewer/viewer_state.h"

namespace pathway {
namespace {

constexpr int kWidth = 64;  // render pixels across; the height follows the scene's camera

struct DemoRun {
  std::shared_ptr<const LoadedScene> scene;
  ViewerState state;
  std::shared_ptr<const LaneFrame> frames[2];
};

// The seeds a check runs over: seed 1, or 1..N with PATHWAY_DEMO_POINT_SEEDS=N.
std::vector<uint64_t> seeds() {
  const char* count = std::getenv("PATHWAY_DEMO_POINT_SEEDS");
  const int n = count ? std::max(1, std::atoi(count)) : 1;
  std::vector<uint64_t> list;
  for (int i = 1; i <= n; ++i) list.push_back(static_cast<uint64_t>(i));
  return list;
}

bool referencesBuiltIn() {
  for (int stage = 1; stage <= 5; ++stage)
    if (!findStageIntegrator(stage, Variant::Reference)) return false;
  return true;
}

// Runs demo `name` with `seed` until each pane has traced `megaRays` million rays (the demos
// compare at equal rays; a machine-independent stand-in for equal time) or reached `spp`.
// `adjust` changes the state first (a depth, a light size), as a key press would.
template <typename Adjust>
DemoRun runDemo(const std::string& name, uint64_t seed, double megaRays, uint32_t spp,
                Adjust adjust) {
  ViewerOptions options;
  applyViewerDemo(name, options);
  DemoRun run;
  run.state = initialState(options);
  run.state.settings.seed = seed;
  run.state.settings.samplesPerPixel = spp;
  run.state.balance = Balance::EqualRays;
  run.state.budgetMegaRays = static_cast<float>(megaRays);
  adjust(run.state);
  run.scene = LoadedScene::load(options.choices.scene, run.state.sceneOptions);
  const int height = run.scene->scene.imageHeight(kWidth);
  RenderWorker worker;
  const uint64_t id = worker.submit(
      makeJob(run.state, run.scene, OrbitCamera(run.scene->scene).pose(), kWidth, height));
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  for (;;) {
    run.frames[0] = worker.frame(0);
    run.frames[1] = worker.frame(1);
    const bool published = run.frames[0] && run.frames[0]->job == id &&
                           (!run.state.split || (run.frames[1] && run.frames[1]->job == id));
    if (published && worker.idle()) break;
    if (std::chrono::steady_clock::now() > deadline) {
      ADD_FAILURE() << name << ": the panes did not finish within 120 s";
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return run;
}

DemoRun runDemo(const std::string& name, uint64_t seed, double megaRays, uint32_t spp) {
  return runDemo(name, seed, megaRays, spp, [](ViewerState&) {});
}

// What the demo's error plot shows: relMSE of each pane against the left pane's stage reference
// at `referenceSpp` (as key M makes it).
std::vector<double> relMse(const DemoRun& run, uint32_t referenceSpp) {
  ReferenceMaker maker;
  maker.start(run.frames[0], run.scene, referenceSpp);
  std::optional<ReferenceImage> reference;
  while (!(reference = maker.take()) && maker.running())
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  if (!reference) {
    ADD_FAILURE() << "no reference: " << maker.error();
    return {};
  }
  std::vector<double> errors;
  for (const auto& frame : run.frames)
    if (frame) errors.push_back(imageError(frame->images.color, reference->image).relMse);
  return errors;
}

double raysPerCameraSample(const LaneFrame& frame) {
  const RayCounters& c = frame.stats.counters;
  return static_cast<double>(c.totalRays()) / static_cast<double>(c.primary);
}

class DemoPoints : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!referencesBuiltIn()) GTEST_SKIP() << "the demos show the reference stages";
  }
};

// One 4D integral over well-spread points beats nested AO with independent numbers at equal rays
// (measured: 4D's relMSE 0.35-0.41 times nested's over seeds 1-10; checked: below 0.5).
TEST_F(DemoPoints, FourDimensionalAoBeatsNestedAtEqualRays) {
  for (uint64_t seed : seeds()) {
    const DemoRun run = runDemo("nested-vs-4d", seed, 2.0, 4096);
    const std::vector<double> e = relMse(run, 256);
    ASSERT_EQ(e.size(), 2u);
    std::printf("nested-vs-4d seed %llu: nested %.4g, 4D %.4g, ratio %.3f\n",
                static_cast<unsigned long long>(seed), e[0], e[1], e[1] / e[0]);
    EXPECT_LT(e[1], 0.5 * e[0]) << "seed " << seed;
  }
}

// Path tracing beats naive recursion, NEE off in both, at equal rays (measured: path's relMSE
// 0.60-0.67 times naive's over seeds 1-10; checked: below 0.8).
TEST_F(DemoPoints, PathTracingBeatsNaiveRecursionAtEqualRays) {
  for (uint64_t seed : seeds()) {
    const DemoRun run = runDemo("naive-vs-path", seed, 4.0, 4096);
    const std::vector<double> e = relMse(run, 256);
    ASSERT_EQ(e.size(), 2u);
    std::printf("naive-vs-path seed %llu: path %.4g, naive %.4g, ratio %.3f\n",
                static_cast<unsigned long long>(seed), e[0], e[1], e[0] / e[1]);
    EXPECT_LT(e[0], 0.8 * e[1]) << "seed " << seed;
  }
}

// NEE's error stays put as the light shrinks at fixed power; without NEE it grows. Measured over
// seeds 1-10: without NEE, 322-378 times NEE's relMSE at half the side, 1321-1689 times at a
// quarter. Checked: at least 10 times at half, and the gap at least twice as wide at a quarter.
TEST_F(DemoPoints, NeeKeepsItsErrorAsTheLightShrinks) {
  for (uint64_t seed : seeds()) {
    double gap[2];
    const float scales[2] = {0.5f, 0.25f};
    for (int i = 0; i < 2; ++i) {
      const DemoRun run = runDemo("nee-small-light", seed, 2.0, 4096, [&](ViewerState& state) {
        state.sceneOptions.lightScale = scales[i];
      });
      const std::vector<double> e = relMse(run, 256);
      ASSERT_EQ(e.size(), 2u);
      gap[i] = e[1] / e[0];
      std::printf("nee-small-light seed %llu light %.2f: NEE %.4g, no NEE %.4g, ratio %.1f\n",
                  static_cast<unsigned long long>(seed), scales[i], e[0], e[1], gap[i]);
    }
    EXPECT_GT(gap[0], 10.0) << "seed " << seed;
    EXPECT_GT(gap[1], 2.0 * gap[0]) << "seed " << seed;
  }
}

// Each step down multiplies naive recursion's rays per camera sample (4 per hit: close to ×4
// where rays stay in the box), while path tracing adds about 2 (a bounce and a shadow ray).
// Checked: at least ×2.5 per step on the left, at most +2.5 on the right, depths 0-4.
TEST_F(DemoPoints, RaysMultiplyWithDepthInNaiveRecursionOnly) {
  double naive[5], path[5];
  for (int depth = 0; depth <= 4; ++depth) {
    const DemoRun run = runDemo("ray-explosion", 1, 1000.0, 1, [&](ViewerState& state) {
      const int start = static_cast<int>(state.params[0].at({4, "depth"}));
      stepRecursionDepth(state, depth - start);
    });
    ASSERT_TRUE(run.frames[0] && run.frames[1]);
    naive[depth] = raysPerCameraSample(*run.frames[0]);
    path[depth] = raysPerCameraSample(*run.frames[1]);
    std::printf("ray-explosion depth %d: naive %.1f, path %.1f rays per camera sample\n", depth,
                naive[depth], path[depth]);
  }
  EXPECT_NEAR(naive[0], 1.0, 1e-9);
  for (int depth = 1; depth <= 4; ++depth) {
    EXPECT_GT(naive[depth], 2.5 * naive[depth - 1]) << "depth " << depth;
    EXPECT_LT(path[depth] - path[depth - 1], 2.5) << "depth " << depth;
  }
  EXPECT_LT(naive[4], 1365.0) << "no more than 1 + 4 + ... + 4^4 rays";
}

// Mitchell's negative lobes ring: beside each edge its image dips below the box's darkest pixel
// and rises above its brightest (the box never leaves the range of the radiance it averages).
TEST_F(DemoPoints, MitchellRingsWhereTheBoxDoesNot) {
  const DemoRun run = runDemo("mitchell-lobes", 1, 1000.0, 64);
  ASSERT_TRUE(run.frames[0] && run.frames[1]);
  auto range = [](const Image& image) {
    float low = 1e30f, high = -1e30f;
    for (const Color& pixel : image.pixels) {
      low = std::min(low, pixel.y);
      high = std::max(high, pixel.y);
    }
    return std::pair<float, float>(low, high);
  };
  const auto [mitchellLow, mitchellHigh] = range(run.frames[0]->images.color);
  const auto [boxLow, boxHigh] = range(run.frames[1]->images.color);
  std::printf("mitchell-lobes: mitchell [%.4f, %.4f], box [%.4f, %.4f]\n", mitchellLow,
              mitchellHigh, boxLow, boxHigh);
  EXPECT_LT(mitchellLow, boxLow - 0.01f);
  EXPECT_GT(mitchellHigh, boxHigh + 0.01f);
}

}  // namespace
}  // namespace pathway

#endif  // PATHWAY_HAS_VIEWER
