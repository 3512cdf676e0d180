// The viewer: its render worker (no GL needed) restarts on every change, cancels slow passes, keeps
// split panes level and counts rays per pixel; end to end, `pathway view` draws the render and the
// panel both offscreen (OSMesa) and in a real window (under Xvfb), and without a display it says
// what to do instead of crashing.
#ifdef PATHWAY_HAS_VIEWER

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <thread>

#include "core/error.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "run_command.h"
#include "viewer/frame_grade.h"
#include "viewer/loaded_scene.h"
#include "viewer/panel.h"
#include "viewer/render_worker.h"
#include "viewer/viewer_demos.h"
#include "viewer/viewer_state.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

const std::string kScene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";

bool registered(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return true;
  return false;
}

// ---- The render worker ----

class ViewerWorker : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = LoadedScene::load(kScene); }
  static void TearDownTestSuite() { scene_.reset(); }

  static WorkerJob job(const std::string& integrator, int width, int height, uint32_t spp) {
    WorkerJob job;
    job.scene = scene_;
    job.lanes = {LaneJob{integrator, {}}};
    job.settings.width = width;
    job.settings.height = height;
    job.settings.samplesPerPixel = spp;
    job.settings.samplesPerPass = 1;
    job.camera = OrbitCamera(scene_->scene).pose();
    return job;
  }

  // Waits (at most `timeout` seconds) for a frame of job `id` in `lane` that satisfies `ready`.
  template <typename Ready>
  static std::shared_ptr<const LaneFrame> waitFor(const RenderWorker& worker, uint64_t id,
                                                  size_t lane, double timeout, Ready ready) {
    const auto deadline = Clock::now() + std::chrono::duration<double>(timeout);
    while (Clock::now() < deadline) {
      auto frame = worker.frame(lane);
      if (frame && frame->job == id && ready(*frame)) return frame;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return nullptr;
  }
  static std::shared_ptr<const LaneFrame> waitForFirst(const RenderWorker& worker, uint64_t id,
                                                       double timeout = 10.0) {
    return waitFor(worker, id, 0, timeout, [](const LaneFrame&) { return true; });
  }

  static std::shared_ptr<const LoadedScene> scene_;
};

std::shared_ptr<const LoadedScene> ViewerWorker::scene_;

TEST_F(ViewerWorker, PublishesAFirstImageQuickly) {
  RenderWorker worker;
  const auto start = Clock::now();
  const uint64_t id = worker.submit(job("stage1", 320, 180, 64));
  const auto frame = waitForFirst(worker, id);
  ASSERT_TRUE(frame);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  // The target is 0.5 s at 640x360; this is a quarter of that, with slack for a loaded machine.
  EXPECT_LT(seconds, 2.0);
  EXPECT_TRUE(frame->error.empty()) << frame->error;
  EXPECT_EQ(frame->images.color.width, 320);
  EXPECT_EQ(frame->images.color.height, 180);
  EXPECT_EQ(frame->images.variance.width, 320);
  EXPECT_GE(frame->stats.samplesPerPixel, 1u);
  EXPECT_GT(frame->firstImageSeconds, 0.0);
}

TEST_F(ViewerWorker, RendersToTheTargetThenRests) {
  RenderWorker worker;
  const uint64_t id = worker.submit(job("stage1", 64, 36, 8));
  const auto frame =
      waitFor(worker, id, 0, 10.0, [](const LaneFrame& f) { return f.stats.samplesPerPixel == 8; });
  ASSERT_TRUE(frame);
  for (int i = 0; i < 1000 && !worker.idle(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  EXPECT_TRUE(worker.idle());
  EXPECT_EQ(worker.frame(0)->stats.samplesPerPixel, 8u);
}

TEST_F(ViewerWorker, RestartsWhenTheJobChanges) {
  RenderWorker worker;
  WorkerJob first = job("stage1", 96, 54, 1 << 20);
  const uint64_t a = worker.submit(first);
  const auto before =
      waitFor(worker, a, 0, 10.0, [](const LaneFrame& f) { return f.stats.samplesPerPixel >= 40; });
  ASSERT_TRUE(before);
  WorkerJob second = first;
  second.settings.seed = 7;
  ASSERT_NE(first, second);
  const uint64_t b = worker.submit(second);
  const auto frame = waitForFirst(worker, b);
  ASSERT_TRUE(frame);
  EXPECT_EQ(frame->settings.seed, 7u);
  EXPECT_LT(frame->stats.samplesPerPixel, before->stats.samplesPerPixel);  // started over
}

TEST_F(ViewerWorker, CancelsASlowPassAtOnce) {
  RenderWorker worker;
  // One pass of 2^20 samples per pixel would take minutes.
  WorkerJob slow = job("stage1", 320, 180, 1 << 20);
  slow.settings.samplesPerPass = 1 << 20;
  worker.submit(slow);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_GT(worker.passSeconds(), 0.0);  // the slow pass is running
  const auto start = Clock::now();
  const uint64_t fast = worker.submit(job("stage1", 320, 180, 64));
  ASSERT_TRUE(waitForFirst(worker, fast));
  EXPECT_LT(std::chrono::duration<double>(Clock::now() - start).count(), 2.0);
}

TEST_F(ViewerWorker, CountsEveryRayInThePixelItCameFrom) {
  RenderWorker worker;
  const uint64_t id = worker.submit(job("stage1", 80, 45, 4));
  const auto frame =
      waitFor(worker, id, 0, 10.0, [](const LaneFrame& f) { return f.stats.samplesPerPixel == 4; });
  ASSERT_TRUE(frame);
  // Eye-light shading traces exactly one ray per sample, so every pixel shows 1 ray per sample.
  size_t exact = 0;
  double total = 0.0;
  for (float rays : frame->raysPerSample) {
    exact += rays == 1.0f;
    total += rays * 4.0;
  }
  EXPECT_EQ(exact, frame->raysPerSample.size());
  EXPECT_DOUBLE_EQ(total, static_cast<double>(frame->stats.counters.totalRays()));
}

TEST_F(ViewerWorker, SplitViewKeepsEqualRayCounts) {
  if (!registered("stage2@ref")) GTEST_SKIP() << "needs the stage 2 reference";
  RenderWorker worker;
  WorkerJob split = job("stage1", 64, 36, 32);
  split.lanes.push_back(LaneJob{"stage2@ref", {{"ao-rays", 4.0}}});
  split.balance = Balance::EqualRays;
  const uint64_t id = worker.submit(split);
  ASSERT_TRUE(waitForFirst(worker, id));
  for (int i = 0; i < 5000 && !worker.idle(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_TRUE(worker.idle());
  const auto left = worker.frame(0), right = worker.frame(1);
  ASSERT_TRUE(left && right);
  // Stage 1 traces 1 ray per sample, nested AO up to 5: the left pane takes more passes, and
  // both end within one pass (of the bigger lane) of each other.
  const double leftRays = static_cast<double>(left->stats.counters.totalRays());
  const double rightRays = static_cast<double>(right->stats.counters.totalRays());
  const double onePass = rightRays / right->stats.samplesPerPixel;
  EXPECT_GT(left->stats.samplesPerPixel, right->stats.samplesPerPixel);
  EXPECT_LE(std::fabs(leftRays - rightRays), onePass);
}

TEST_F(ViewerWorker, ReportsALaneThatCannotStart) {
  RenderWorker worker;
  WorkerJob bad = job("stage9", 32, 18, 4);
  bad.lanes.push_back(LaneJob{"stage1", {}});
  const uint64_t id = worker.submit(bad);
  const auto frame = waitForFirst(worker, id);
  ASSERT_TRUE(frame);
  EXPECT_NE(frame->error.find("stage9"), std::string::npos) << frame->error;
  // The other pane renders anyway.
  EXPECT_TRUE(waitFor(worker, id, 1, 10.0, [](const LaneFrame& f) { return f.error.empty(); }));
}

TEST_F(ViewerWorker, RefusesParameterValuesOutsideTheirDeclarationInsteadOfClamping) {
  RenderWorker worker;
  WorkerJob bad = job("stage2", 32, 18, 4);
  bad.lanes[0].params["ao-rays"] = 5000;  // declared range [1, 1024]
  const uint64_t id = worker.submit(bad);
  const auto frame = waitForFirst(worker, id);
  ASSERT_TRUE(frame);
  EXPECT_NE(frame->error.find("ao-rays"), std::string::npos) << frame->error;
  EXPECT_NE(frame->error.find("[1, 1024]"), std::string::npos) << frame->error;
  EXPECT_TRUE(frame->images.color.pixels.empty());
}

TEST(ViewerState, PanelValuesAreCheckedAndShareOneDeclaration) {
  ViewerState state;
  EXPECT_EQ(state.settings.samplesPerPixel, kViewerSamplesPerPixel.defaultAs<uint32_t>());
  const IntegratorInfo& info = findIntegrator("stage5");
  const OptionSpec* lightPick = nullptr;
  for (const OptionSpec& spec : info.params)
    if (spec.name == "light-pick") lightPick = &spec;
  ASSERT_NE(lightPick, nullptr);
  EXPECT_EQ(lightPick->kind, OptionKind::Choice);  // the panel draws a combo box, not a checkbox
  setParamValue(state, 0, info, *lightPick, 0.0);
  EXPECT_EQ(paramValue(state, 0, info, *lightPick), 0.0);
  EXPECT_THROW(setParamValue(state, 0, info, *lightPick, 2.0), PathwayError);
  EXPECT_EQ(paramValue(state, 0, info, *lightPick), 0.0);
  // The job carries every declared parameter and where the earlier stages come from.
  state.integrator[0] = "stage5";
  state.earlierStages[0] = EarlierStages::Reference;
  const WorkerJob job = makeJob(state, nullptr, CameraPose{}, 8, 8);
  ASSERT_EQ(job.lanes.size(), 1u);
  EXPECT_EQ(job.lanes[0].params.size(), info.params.size());
  EXPECT_EQ(job.lanes[0].earlierStages, EarlierStages::Reference);
}

// Key G: the shown image graded against the reference rendered at the same view.
TEST_F(ViewerWorker, GradesTheShownImageAgainstTheReference) {
  if (!registered("stage2@ref")) GTEST_SKIP() << "needs the stage 2 reference";
  RenderWorker worker;
  auto finished = [](const LaneFrame& f) { return f.stats.samplesPerPixel == 8; };
  const uint64_t reference = worker.submit(job("stage2@ref", 64, 48, 8));
  const auto referenceFrame = waitFor(worker, reference, 0, 20.0, finished);
  ASSERT_TRUE(referenceFrame);
  ASSERT_TRUE(canGradeFrame(*referenceFrame));
  const FrameGrade same = gradeFrame(*referenceFrame, *scene_);
  EXPECT_TRUE(same.error.empty()) << same.error;
  EXPECT_TRUE(same.passed) << same.summary;
  EXPECT_EQ(same.heatmap.width, 64);
  // Graded against the reference's fastest version (render/wavefront.h).
  const std::string reference2 = referenceIntegratorName(2, ReferenceTracing::Fastest);
  EXPECT_EQ(same.reference, reference2);

  WorkerJob skeleton = job("stage2", 64, 48, 8);
  skeleton.lanes[0].earlierStages = EarlierStages::Reference;
  const auto skeletonFrame = waitFor(worker, worker.submit(skeleton), 0, 20.0, finished);
  ASSERT_TRUE(skeletonFrame);
  const FrameGrade wrong = gradeFrame(*skeletonFrame, *scene_);
  EXPECT_FALSE(wrong.passed) << wrong.summary;
  EXPECT_GT(wrong.comparison.failingTiles, 0u);
  EXPECT_NE(wrong.summary.find("differs from " + reference2), std::string::npos) << wrong.summary;
}

TEST(ViewerScene, MissingFileIsAnError) {
  EXPECT_THROW(LoadedScene::load("/nowhere/scene.gltf"), PathwayError);
}

// ---- `pathway view` end to end ----

using Outcome = test::CommandOutcome;
const auto run = test::runCommand;

class ViewerCli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder("pathway_viewer"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  // The screenshot shows the whole UI: a render of the Cornell box right of the panel (red and
  // green walls, varied values) and the ImGui panel on the left (its background and its text).
  static void expectViewerPixels(const std::string& file, int width, int height) {
    const Image image = readImageFile(file).images.color;
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    const int panel = static_cast<int>(kPanelWidth);

    size_t red = 0, green = 0, count = 0;
    double sum = 0.0, sumSquares = 0.0;
    for (int y = 10; y < height - 10; ++y)
      for (int x = panel + 10; x < width - 10; ++x) {
        const Color& c = image.at(x, y);
        red += c.x > 0.25f && c.x > 1.8f * c.y && c.x > 1.8f * c.z;
        green += c.y > 0.2f && c.y > 1.5f * c.x && c.y > 1.5f * c.z;
        const double luminance = (c.x + c.y + c.z) / 3.0;
        sum += luminance;
        sumSquares += luminance * luminance;
        ++count;
      }
    const double mean = sum / count;
    EXPECT_GT(red, count / 50) << "no red wall in the render region";
    EXPECT_GT(green, count / 50) << "no green wall in the render region";
    EXPECT_GT(std::sqrt(sumSquares / count - mean * mean), 0.1) << "the render region is flat";

    // ImGui's dark window background is (0.06, 0.06, 0.06) = 15/255.
    size_t background = 0, text = 0, panelCount = 0;
    for (int y = 30; y < height; ++y)
      for (int x = 0; x < panel - 20; ++x) {
        const Color& c = image.at(x, y);
        background += std::fabs(c.x - 15.0f / 255) < 0.01f &&
                      std::fabs(c.y - 15.0f / 255) < 0.01f && std::fabs(c.z - 15.0f / 255) < 0.01f;
        text += c.x > 0.75f && c.y > 0.75f && c.z > 0.75f;
        ++panelCount;
      }
    EXPECT_GT(background, panelCount / 4) << "no ImGui panel background";
    EXPECT_GT(text, 500u) << "no text in the panel";
  }

  fs::path dir_;
};

// Under the sanitizer build, LeakSanitizer reports allocations the Mesa GL drivers make and never
// free (in modules unloaded at exit, so no suppression can name them). Leak checking is turned
// off for these GL processes only; address and undefined-behaviour checks stay on, and every
// other test keeps leak checking.
const std::string kViewCommand = "env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " +
                                 std::string(PATHWAY_BINARY) + " view " + kScene +
                                 " --window-width 960 --window-height 540 --frames 30";

TEST_F(ViewerCli, HeadlessScreenshotShowsRenderAndPanel) {
  const Outcome outcome = run(kViewCommand + " --headless --screenshot " + path("ui.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  ASSERT_TRUE(fs::exists(path("ui.png"))) << outcome.output;
  expectViewerPixels(path("ui.png"), 960, 540);
}

TEST_F(ViewerCli, WindowScreenshotUnderXvfb) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1 && command -v Xvfb >/dev/null 2>&1") != 0)
    GTEST_SKIP() << "Xvfb is not installed";
  // xvfb-run picks a free display (-a), and stops its server when the viewer exits.
  const Outcome outcome = run("xvfb-run -a -s '-screen 0 1280x800x24' " + kViewCommand +
                              " --screenshot " + path("window.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  ASSERT_TRUE(fs::exists(path("window.png"))) << outcome.output;
  expectViewerPixels(path("window.png"), 960, 540);
}

// Every lecture demo names a scene that exists and integrators, parameters and settings that
// `pathway render` would accept, for both panes.
TEST(ViewerDemos, EveryDemoIsAValidStartingPoint) {
  if (!registered("stage5@ref")) GTEST_SKIP() << "the demos show the reference stages";
  for (const ViewerDemo& demo : viewerDemos()) {
    ViewerOptions options;
    applyViewerDemo(demo.name, options);
    EXPECT_TRUE(fs::is_regular_file(options.choices.scene)) << demo.name;
    EXPECT_NO_THROW(options.choices.recipe()) << demo.name;
    if (!demo.splitIntegrator.empty()) {
      RenderChoices right = options.choices;
      right.integrator = options.splitIntegrator;
      right.params = options.splitParams;
      EXPECT_NO_THROW(right.recipe()) << demo.name;
    }
    EXPECT_FALSE(demo.shows.empty()) << demo.name;
  }
  ViewerOptions options;
  try {
    applyViewerDemo("no-such-demo", options);
    ADD_FAILURE() << "an unknown demo was accepted";
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find("nested-vs-4d"), std::string::npos) << error.what();
  }
}

// A demo starts straight into its split view: both panes show an AO render of the Cornell box
// (not flat), and the error plot's reference is made (small here, to keep the test short).
TEST_F(ViewerCli, ADemoStartsIntoItsSplitView) {
  if (!registered("stage3@ref")) GTEST_SKIP() << "the demo shows the reference stages";
  const Outcome outcome = run("env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " +
                              std::string(PATHWAY_BINARY) +
                              " view --demo nested-vs-4d --reference-spp 16 --headless --frames 10 "
                              "--window-width 960 --window-height 540 --screenshot " +
                              path("demo.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  const Image image = readImageFile(path("demo.png")).images.color;
  EXPECT_NE(outcome.output.find("error plot, left stage2@ref"), std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("error plot, right stage3@ref"), std::string::npos)
      << outcome.output;
  // Each half of the render region (right of the panel) shows a render, not a flat colour.
  const int panel = static_cast<int>(kPanelWidth), half = (image.width - panel) / 2;
  for (int pane = 0; pane < 2; ++pane) {
    double sum = 0.0, sumSquares = 0.0;
    size_t count = 0;
    for (int y = 150; y < image.height - 10; ++y)
      for (int x = panel + pane * half + 5; x < panel + (pane + 1) * half - 5; ++x, ++count) {
        const double luminance = image.at(x, y).x;
        sum += luminance;
        sumSquares += luminance * luminance;
      }
    const double mean = sum / count;
    EXPECT_GT(std::sqrt(sumSquares / count - mean * mean), 0.1) << "pane " << pane << " is flat";
    EXPECT_GT(mean, 0.2) << "pane " << pane << " is dark";
  }
  const Outcome unknown = run(std::string(PATHWAY_BINARY) + " view --demo nope --headless");
  EXPECT_EQ(unknown.exitCode, 1);
  EXPECT_NE(unknown.output.find("unknown demo 'nope'"), std::string::npos) << unknown.output;
}

TEST_F(ViewerCli, WithoutADisplaySaysToUseHeadless) {
  const Outcome outcome = run("env -u DISPLAY -u WAYLAND_DISPLAY " + kViewCommand);
  EXPECT_NE(outcome.exitCode, 0);
  EXPECT_NE(outcome.output.find("--headless"), std::string::npos) << outcome.output;
  EXPECT_EQ(outcome.output.find("internal error"), std::string::npos) << outcome.output;
}

TEST_F(ViewerCli, OutOfRangeParameterIsRefusedBeforeAnyWindowAsRenderDoes) {
  const Outcome outcome =
      run(kViewCommand + " --headless -i stage2 -p ao-rays=5000 --screenshot " + path("x.png"));
  EXPECT_EQ(outcome.exitCode, 1);
  EXPECT_NE(outcome.output.find("ao-rays"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("[1, 1024]"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

TEST_F(ViewerCli, UnknownIntegratorIsRefusedBeforeAnyWindow) {
  const Outcome outcome = run(kViewCommand + " --headless -i stage9 --screenshot " + path("x.png"));
  EXPECT_EQ(outcome.exitCode, 1);
  EXPECT_NE(outcome.output.find("stage9"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(path("x.png")));
}

}  // namespace
}  // namespace pathway

#endif  // PATHWAY_HAS_VIEWER
