// The viewer: its render worker (no GL needed) restarts on every change, cancels slow passes, keeps
// split panes level and counts rays per pixel; end to end, `pathway view` draws the render and the
// panel both offscreen (OSMesa) and in a real window (under Xvfb), and without a display it says
// what to do instead of crashing.
#ifdef PATHWAY_HAS_VIEWER

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/error.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "run_command.h"
#include "viewer/display_image.h"
#include "viewer/frame_grade.h"
#include "viewer/key_queue.h"
#include "viewer/loaded_scene.h"
#include "viewer/panel.h"
#include "viewer/render_worker.h"
#include "viewer/shortcut_keys.h"
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

// Key T: yours <-> the reference the other pane shows, so the two labels name the same
// integrator (stage5@ref, not its wavefront twin stage5@fast); alone, the one the pane left.
TEST(ViewerState, ToggleReturnsToTheReferenceTheOtherPaneShows) {
  if (!registered("stage5@ref") || !registered("stage5@fast") || !registered("stage5"))
    GTEST_SKIP() << "needs stage 5 yours, its reference and its wavefront version";
  ViewerState state;
  state.split = true;
  state.integrator[0] = state.integrator[1] = "stage5@ref";
  ASSERT_TRUE(toggleVariant(state, 0));
  EXPECT_EQ(state.integrator[0], "stage5");
  ASSERT_TRUE(toggleVariant(state, 0));
  EXPECT_EQ(state.integrator[0], "stage5@ref");
  EXPECT_EQ(state.integrator[0], state.integrator[1]);

  state.integrator[1] = "stage5@fast";  // the right pane's reference is the one to match
  ASSERT_TRUE(toggleVariant(state, 0));
  ASSERT_TRUE(toggleVariant(state, 0));
  EXPECT_EQ(state.integrator[0], "stage5@fast");

  // One pane: back to the reference it left.
  state.split = false;
  state.integrator[0] = "stage5@ref";
  ASSERT_TRUE(toggleVariant(state, 0));
  ASSERT_TRUE(toggleVariant(state, 0));
  EXPECT_EQ(state.integrator[0], "stage5@ref");

  // Keys 1-5 keep the labels matching too: stage 3 beside stage3@ref is stage3@ref.
  if (!registered("stage3@ref")) return;
  state.split = true;
  state.integrator[1] = "stage3@ref";
  ASSERT_TRUE(selectStage(state, 0, 3));
  EXPECT_EQ(state.integrator[0], "stage3@ref");
}

// A tap shorter than a frame (pressed and released between two frames) is queued by GLFW's key
// callback and acted on once, at the next frame; at 4-10 frames/s polling lost 2 taps of 7.
TEST(ViewerKeys, APressAndReleaseWithinOneFrameActsOnce) {
  ViewerState state;
  KeyQueue queue;
  queue.onKey(GLFW_KEY_D, GLFW_PRESS, 0);
  queue.onKey(GLFW_KEY_D, GLFW_RELEASE, 0);  // released before the frame drains the queue
  ShortcutEffects effects = applyKeyPresses(state, queue.take());
  EXPECT_EQ(state.display, DisplayMode::Variance);
  effects = applyKeyPresses(state, queue.take());  // the next frame: nothing left to act on
  EXPECT_EQ(state.display, DisplayMode::Variance);

  // Seven quick taps in one slow frame: seven steps, none lost; a held key's repeats are not.
  for (int tap = 0; tap < 7; ++tap) {
    queue.onKey(GLFW_KEY_EQUAL, GLFW_PRESS, 0);
    queue.onKey(GLFW_KEY_EQUAL, GLFW_REPEAT, 0);
    queue.onKey(GLFW_KEY_EQUAL, GLFW_RELEASE, 0);
  }
  applyKeyPresses(state, queue.take());
  EXPECT_EQ(state.exposure, 7.0f);

  // Shift sends the pane keys to the right pane in the split view; the effects reach the viewer.
  state.split = true;
  queue.onKey(GLFW_KEY_V, GLFW_PRESS, 0);
  queue.onKey(GLFW_KEY_V, GLFW_RELEASE, 0);
  queue.onKey(GLFW_KEY_B, GLFW_PRESS, 0);
  queue.onKey(GLFW_KEY_M, GLFW_PRESS, 0);
  effects = applyKeyPresses(state, queue.take());
  EXPECT_FALSE(state.split);
  EXPECT_EQ(state.balance, Balance::EqualRays);
  EXPECT_TRUE(effects.makeReference);
  EXPECT_FALSE(effects.grade);
  if (!registered("stage2") || !registered("stage3")) return;
  state.split = true;
  state.integrator[0] = state.integrator[1] = "stage2";
  queue.onKey(GLFW_KEY_3, GLFW_PRESS, GLFW_MOD_SHIFT);
  applyKeyPresses(state, queue.take());
  EXPECT_EQ(state.integrator[0], "stage2");
  EXPECT_EQ(state.integrator[1], "stage3");
}

// Up / Down step the depth of the panes that recurse (the ray explosion), within their range;
// [ / ] halve and double the lights within the setting's range, and ask for the scene again.
TEST(ViewerKeys, DepthAndLightSizeStepWithinTheirRanges) {
  if (!registered("stage4@ref") || !registered("stage5@ref") || !registered("stage2@ref"))
    GTEST_SKIP() << "needs the reference stages";
  ViewerState state;
  state.split = true;
  state.integrator[0] = "stage4@ref";
  state.integrator[1] = "stage5@ref";
  const IntegratorInfo& naive = findIntegrator("stage4@ref");
  const IntegratorInfo& path = findIntegrator("stage5@ref");
  auto depth = [&](int lane, const IntegratorInfo& info) {
    for (const OptionSpec& spec : info.params)
      if (spec.role == OptionRole::RecursionDepth) return paramValue(state, lane, info, spec);
    ADD_FAILURE() << info.name << " declares no recursion depth";
    return -2.0;
  };
  const double naiveStart = depth(0, naive), pathStart = depth(1, path);
  KeyQueue queue;
  auto press = [&](int key) {
    queue.onKey(key, GLFW_PRESS, 0);
    return applyKeyPresses(state, queue.take());
  };
  press(GLFW_KEY_UP);
  EXPECT_EQ(depth(0, naive), naiveStart + 1);
  EXPECT_EQ(depth(1, path), pathStart + 1);
  for (int i = 0; i < 100; ++i) press(GLFW_KEY_DOWN);
  EXPECT_EQ(depth(0, naive), 0.0);
  EXPECT_EQ(depth(1, path), 0.0) << "-1 (no limit) is not one step below 0";
  state.integrator[0] = "stage2@ref";  // no depth: left alone, no error
  EXPECT_NO_THROW(press(GLFW_KEY_UP));
  EXPECT_EQ(depth(1, path), 1.0);

  EXPECT_TRUE(press(GLFW_KEY_LEFT_BRACKET).resizeLights);
  EXPECT_FLOAT_EQ(state.sceneOptions.lightScale, 0.5f);
  EXPECT_TRUE(press(GLFW_KEY_RIGHT_BRACKET).resizeLights);
  EXPECT_FLOAT_EQ(state.sceneOptions.lightScale, 1.0f);
  for (int i = 0; i < 20; ++i) press(GLFW_KEY_LEFT_BRACKET);
  EXPECT_FLOAT_EQ(state.sceneOptions.lightScale, setting::kLightScale.minValue);
  EXPECT_FALSE(press(GLFW_KEY_LEFT_BRACKET).resizeLights) << "at the bottom: nothing to load";
}

// Rays per camera sample multiply with depth: on a log scale each ×N is one equal step, so the
// ray explosion's fixed scale (1 to 1365) shows every depth as a colour of its own.
TEST(ViewerDisplay, RaysAreShownOnALogScaleAndVarianceOnALinearOne) {
  EXPECT_FLOAT_EQ(falseColorPosition(DisplayMode::RayHeatmap, 1.0f, 1365.0f), 0.0f);
  EXPECT_FLOAT_EQ(falseColorPosition(DisplayMode::RayHeatmap, 4.0f, 16.0f), 0.5f);
  EXPECT_FLOAT_EQ(falseColorPosition(DisplayMode::RayHeatmap, 0.0f, 16.0f), 0.0f);
  EXPECT_FLOAT_EQ(falseColorPosition(DisplayMode::Variance, 4.0f, 16.0f), 0.25f);
  const float depth2 = falseColorPosition(DisplayMode::RayHeatmap, 21.0f, 1365.0f);
  const float depth3 = falseColorPosition(DisplayMode::RayHeatmap, 85.0f, 1365.0f);
  EXPECT_GT(depth3 - depth2, 0.18f) << "one depth step is a fifth of the scale";
}

// A window leaves its UI thread a core; one core is shared.
TEST(ViewerState, RendersBesideTheUiOnOneCoreFewer) {
  EXPECT_EQ(renderThreadsBesideUi(2), 1);
  EXPECT_EQ(renderThreadsBesideUi(8), 7);
  EXPECT_EQ(renderThreadsBesideUi(1), 0);  // 0: all (the one)
}

// A frame whose variance image is `variance` everywhere but one pixel (the 1 % above the scale).
LaneFrame varianceFrame(float variance) {
  LaneFrame frame;
  frame.images.color = Image(10, 10);
  frame.images.variance = Image(10, 10);
  for (Color& pixel : frame.images.variance.pixels) pixel = Color(variance);
  return frame;
}

// Side by side, the variance display has one colour scale for both panes: with one each, the NEE
// pane (7.6e-8) would look as noisy as the other (0.255).
TEST(ViewerDisplay, SplitPanesShareOneFalseColourScale) {
  const LaneFrame quiet = varianceFrame(7.6e-8f), noisy = varianceFrame(0.255f);
  const LaneFrame* frames[2] = {&quiet, &noisy};
  const float top = sharedScaleTop(frames, 2, DisplayMode::Variance);
  EXPECT_FLOAT_EQ(top, 0.255f);
  const DisplayImage left = makeDisplayImage(quiet, DisplayMode::Variance, 0.0f, top);
  const DisplayImage right = makeDisplayImage(noisy, DisplayMode::Variance, 0.0f, top);
  EXPECT_FLOAT_EQ(left.scaleMax, right.scaleMax);
  uint8_t bottom[3], full[3];
  falseColor(0.0f, bottom);
  falseColor(1.0f, full);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(left.rgba[c], bottom[c]) << "the quiet pane is at the bottom of the shared scale";
    EXPECT_EQ(right.rgba[c], full[c]);
  }
  // Its own scale (no shared one) would have filled it: the bug this guards against.
  const DisplayImage own = makeDisplayImage(quiet, DisplayMode::Variance, 0.0f);
  EXPECT_FLOAT_EQ(own.scaleMax, 7.6e-8f);
  EXPECT_EQ(sharedScaleTop(frames, 2, DisplayMode::Color), 0.0f);
}

// Each pane can have its own sampler (nested-vs-4d: independent numbers against Sobol' points)
// and its own pixel filter (mitchell-lobes: Mitchell against box).
TEST_F(ViewerWorker, EachPaneRendersWithItsOwnSamplerAndFilter) {
  if (!registered("stage2@ref") || !registered("stage3@ref")) GTEST_SKIP() << "needs references";
  ViewerState state;
  state.split = true;
  state.integrator[0] = "stage2@ref";
  state.integrator[1] = "stage3@ref";
  state.settings.sampler = SamplerType::Independent;
  state.splitSampler = SamplerType::Sobol;
  state.splitFilter = FilterType::MitchellNetravali;
  state.settings.samplesPerPixel = 2;
  WorkerJob job = makeJob(state, scene_, OrbitCamera(scene_->scene).pose(), 32, 24);
  ASSERT_EQ(job.lanes.size(), 2u);
  EXPECT_FALSE(job.lanes[0].sampler);
  ASSERT_TRUE(job.lanes[1].sampler);
  EXPECT_EQ(*job.lanes[1].sampler, SamplerType::Sobol);
  RenderWorker worker;
  const uint64_t id = worker.submit(job);
  auto any = [](const LaneFrame&) { return true; };
  const auto left = waitFor(worker, id, 0, 20.0, any), right = waitFor(worker, id, 1, 20.0, any);
  ASSERT_TRUE(left && right);
  EXPECT_EQ(left->settings.sampler, SamplerType::Independent);
  EXPECT_EQ(right->settings.sampler, SamplerType::Sobol);
  EXPECT_EQ(left->settings.filter, FilterType::Box);
  EXPECT_EQ(right->settings.filter, FilterType::MitchellNetravali);
  // Another sampler on the right is another job: the panes restart.
  state.splitSampler.reset();
  EXPECT_FALSE(makeJob(state, scene_, OrbitCamera(scene_->scene).pose(), 32, 24) == job);
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
    EXPECT_FALSE(demo.keys.empty()) << demo.name << " says which keys drive it";
    EXPECT_EQ(demo.keys.find('\n'), std::string::npos) << demo.name;
    if (!demo.splitSampler.empty()) {
      EXPECT_NO_THROW(parseSamplerType(demo.splitSampler)) << demo.name;
    }
    if (!demo.splitFilter.empty()) {
      EXPECT_NO_THROW(parseFilterType(demo.splitFilter)) << demo.name;
    }
  }
  ViewerOptions options;
  try {
    applyViewerDemo("no-such-demo", options);
    ADD_FAILURE() << "an unknown demo was accepted";
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find("nested-vs-4d"), std::string::npos) << error.what();
  }
}

// The demos compare fairly: nested AO with independent numbers against one 4D integral over
// Sobol' points at equal rays; path tracing without NEE (its own demo) against naive recursion.
TEST(ViewerDemos, ComparePanesThatDifferInTheirPointOnly) {
  ViewerOptions nested;
  applyViewerDemo("nested-vs-4d", nested);
  EXPECT_EQ(nested.choices.integrator, "stage2@ref");
  EXPECT_EQ(nested.choices.sampler, "independent");
  EXPECT_EQ(nested.splitIntegrator, "stage3@ref");
  EXPECT_EQ(nested.splitSampler, "sobol");
  EXPECT_EQ(nested.balance, "rays");
  EXPECT_NE(std::find(nested.choices.params.begin(), nested.choices.params.end(), "ao-rays=4"),
            nested.choices.params.end());
  ViewerOptions naive;
  applyViewerDemo("naive-vs-path", naive);
  EXPECT_NE(std::find(naive.choices.params.begin(), naive.choices.params.end(), "nee=off"),
            naive.choices.params.end());
  EXPECT_EQ(naive.balance, "time");
  ViewerOptions lobes;
  applyViewerDemo("mitchell-lobes", lobes);
  EXPECT_EQ(lobes.choices.filter, "mitchell");
  EXPECT_EQ(lobes.splitIntegrator, "stage1@ref");
  EXPECT_EQ(lobes.splitFilter, "box");
  EXPECT_EQ(lobes.balance, "rays");
  // Another demo after it leaves no right-pane sampler or filter behind.
  applyViewerDemo("naive-vs-path", nested);
  EXPECT_TRUE(nested.splitSampler.empty());
  applyViewerDemo("naive-vs-path", lobes);
  EXPECT_TRUE(lobes.splitFilter.empty());
}

// `--list-demos`: each demo, what it shows, its command and the keys that drive it; the command
// line runs as printed (the keys are a shell comment) and the names stay the lines' first words.
TEST_F(ViewerCli, ListsEachDemoWithItsKeys) {
  const Outcome outcome = run(std::string(PATHWAY_BINARY) + " view --list-demos");
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  for (const ViewerDemo& demo : viewerDemos()) {
    EXPECT_NE(outcome.output.find(demo.name + " "), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find(describeViewerDemo(demo) + "   # keys: " + demo.keys + "\n"),
              std::string::npos)
        << outcome.output;
  }
  EXPECT_NE(outcome.output.find("--split-sampler sobol"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("--split-filter box"), std::string::npos) << outcome.output;
}

// Before class, --prepare-demos makes each demo's reference once; the demo then finds it (the plot
// needs no render of its own), and only for exactly its view and spp.
TEST_F(ViewerCli, APreparedDemoFindsItsReferenceInTheCache) {
  if (!registered("stage5@ref")) GTEST_SKIP() << "the demos show the reference stages";
  const std::string env =
      "env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 "
      "XDG_CACHE_HOME=" +
      path("cache") + " " + std::string(PATHWAY_BINARY);
  const Outcome prepared = run(env + " view --prepare-demos --reference-spp 16 --width 32");
  ASSERT_EQ(prepared.exitCode, 0) << prepared.output;
  const fs::path folder = dir_ / "cache" / "pathway" / "references";
  size_t images = 0;
  for (const auto& entry : fs::directory_iterator(folder))
    images += entry.path().extension() == ".exr";
  size_t demosWithReference = 0;
  for (const ViewerDemo& demo : viewerDemos()) demosWithReference += demo.makeReference;
  EXPECT_EQ(images, demosWithReference) << prepared.output;

  const std::string demo = env +
                           " view --demo nee-small-light --headless --frames 2 --width 32 "
                           "--screenshot " +
                           path("demo.png");
  const Outcome found = run(demo + " --reference-spp 16");
  ASSERT_EQ(found.exitCode, 0) << found.output;
  EXPECT_NE(found.output.find("error plot reference: stage5@fast, 16 spp, cached"),
            std::string::npos)
      << found.output;
  // Another spp is another reference: made, not found.
  const Outcome other = run(demo + " --reference-spp 32");
  ASSERT_EQ(other.exitCode, 0) << other.output;
  EXPECT_EQ(other.output.find("cached"), std::string::npos) << other.output;
  // An entry whose key does not match (a damaged or colliding file) is a miss, made again.
  for (const auto& entry : fs::directory_iterator(folder))
    if (entry.path().extension() == ".key") std::ofstream(entry.path()) << "something else";
  const Outcome damaged = run(demo + " --reference-spp 16");
  ASSERT_EQ(damaged.exitCode, 0) << damaged.output;
  EXPECT_EQ(damaged.output.find("cached"), std::string::npos) << damaged.output;
}

// A demo starts straight into its split view: both panes show an AO render of the Cornell box
// (not flat), and the error plot's reference is made (small here, to keep the test short).
TEST_F(ViewerCli, ADemoStartsIntoItsSplitView) {
  if (!registered("stage3@ref")) GTEST_SKIP() << "the demo shows the reference stages";
  const Outcome outcome =
      run("env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 " +
          std::string("XDG_CACHE_HOME=") + path("cache") + " " + std::string(PATHWAY_BINARY) +
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
