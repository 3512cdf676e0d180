// The viewer's error plot: each pane's relMSE history against a reference (starts afresh on a new
// job, in time order, falls as samples grow on a real render), references loaded from files and
// made on demand (with a clear message when they do not fit the panes), the log axes, and
// `pathway view --reference` end to end, headless.
#ifdef PATHWAY_HAS_VIEWER

#include "viewer/error_plot.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "chart/image_error.h"
#include "core/error.h"
#include "engine/recipe_builder.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "run_command.h"
#include "test_scenes.h"
#include "viewer/reference_image.h"
#include "viewer/reference_maker.h"
#include "viewer/stage_reference.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

bool registered(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return true;
  return false;
}

// A frame as the render worker publishes it, of a flat image.
LaneFrame flatFrame(uint64_t job, uint32_t spp, double seconds, float value, int size = 4) {
  LaneFrame frame;
  frame.job = job;
  frame.scenePath = "scene.gltf";
  frame.integrator = "stage1";
  frame.settings.width = frame.settings.height = size;
  frame.images.color = Image(size, size);
  for (Color& pixel : frame.images.color.pixels) pixel = Color(value);
  frame.stats.samplesPerPixel = spp;
  frame.stats.seconds = seconds;
  return frame;
}

ReferenceImage flatReference(const LaneFrame& frame, float value, bool fromFile = false) {
  ReferenceImage reference;
  reference.image = Image(frame.images.color.width, frame.images.color.height);
  for (Color& pixel : reference.image.pixels) pixel = Color(value);
  reference.fromFile = fromFile;
  reference.view = viewOf(frame);
  return reference;
}

TEST(ErrorHistory, StartsAfreshOnANewJob) {
  const ReferenceImage reference = flatReference(flatFrame(1, 1, 0.1, 1.0f), 1.0f);
  ErrorHistory history;
  history.add(flatFrame(1, 1, 0.1, 2.0f), reference);
  history.add(flatFrame(1, 2, 0.2, 1.5f), reference);
  ASSERT_EQ(history.points().size(), 2u);
  EXPECT_EQ(history.job(), 1u);
  history.add(flatFrame(2, 1, 0.05, 3.0f), reference);  // the camera moved: a new job
  ASSERT_EQ(history.points().size(), 1u);
  EXPECT_EQ(history.job(), 2u);
  EXPECT_EQ(history.points()[0].spp, 1u);
  EXPECT_DOUBLE_EQ(history.points()[0].seconds, 0.05);
}

// V and B submit a new job: the plot shows that job's series from then on, empty until its first
// image, never the old job's (whose images the panes still show for a moment).
TEST(ErrorHistory, ARestartShowsOnlyTheNewJobsSeries) {
  const ReferenceImage reference = flatReference(flatFrame(1, 1, 0.1, 1.0f), 1.0f);
  ErrorHistory history;
  history.add(flatFrame(1, 1, 0.1, 2.0f), reference);
  history.add(flatFrame(1, 2, 0.2, 1.5f), reference);
  ASSERT_EQ(history.points().size(), 2u);
  history.restart(2, "stage5@ref");  // V: split off
  EXPECT_TRUE(history.points().empty());
  EXPECT_EQ(history.integrator(), "stage5@ref");
  history.add(flatFrame(1, 4, 0.4, 1.2f), reference);  // the old job's image, still shown
  EXPECT_TRUE(history.points().empty());
  EXPECT_EQ(history.job(), 2u);
  history.add(flatFrame(2, 1, 0.05, 3.0f), reference);
  ASSERT_EQ(history.points().size(), 1u);
  history.restart(3, "stage5@ref");  // V: split on again
  history.add(flatFrame(2, 2, 0.1, 2.0f), reference);
  EXPECT_TRUE(history.points().empty());
}

TEST(ErrorHistory, RecordsEachNewImageInTimeOrder) {
  const ReferenceImage reference = flatReference(flatFrame(1, 1, 0.1, 1.0f), 1.0f);
  ErrorHistory history;
  const LaneFrame frames[] = {flatFrame(1, 1, 0.1, 2.0f), flatFrame(1, 4, 0.3, 1.5f),
                              flatFrame(1, 16, 1.2, 1.25f)};
  for (const LaneFrame& frame : frames) {
    history.add(frame, reference);
    history.add(frame, reference);  // drawn twice: measured once
  }
  ASSERT_EQ(history.points().size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    const ErrorPoint& point = history.points()[i];
    EXPECT_EQ(point.spp, frames[i].stats.samplesPerPixel);
    EXPECT_DOUBLE_EQ(point.seconds, frames[i].stats.seconds);
    EXPECT_DOUBLE_EQ(point.relMse, imageError(frames[i].images.color, reference.image).relMse);
    if (i > 0) {
      EXPECT_GT(point.seconds, history.points()[i - 1].seconds);
    }
  }
  EXPECT_TRUE(history.message().empty()) << history.message();
  // (2 − 1)² / (1 + ε): relMSE is relative to the reference, with ε for black pixels.
  EXPECT_NEAR(history.points()[0].relMse, 1.0 / (1.0 + kRelMseEpsilon), 1e-12);
}

TEST(ErrorHistory, ASizeMismatchedReferenceSaysWhatToDo) {
  const LaneFrame frame = flatFrame(1, 1, 0.1, 1.0f, 4);
  ReferenceImage reference = flatReference(flatFrame(1, 1, 0.1, 1.0f, 8), 1.0f, true);
  ErrorHistory history;
  history.add(frame, reference);  // no throw, no point: a message
  EXPECT_TRUE(history.points().empty());
  const std::string& message = history.message();
  EXPECT_NE(message.find("8 x 8"), std::string::npos) << message;
  EXPECT_NE(message.find("4 x 4"), std::string::npos) << message;
  EXPECT_NE(message.find("--width 8 --height 8"), std::string::npos) << message;
}

TEST(ErrorHistory, AReferenceGoesStaleWhenTheViewChanges) {
  const LaneFrame frame = flatFrame(1, 1, 0.1, 1.0f);
  const ReferenceImage reference = flatReference(frame, 1.0f);
  EXPECT_EQ(referenceProblem(reference, frame), "");

  LaneFrame moved = flatFrame(2, 1, 0.1, 1.0f);
  moved.camera.position.x += 0.5f;
  EXPECT_NE(referenceProblem(reference, moved).find("stale: the camera moved"), std::string::npos)
      << referenceProblem(reference, moved);
  LaneFrame resized = flatFrame(3, 1, 0.1, 1.0f, 6);
  EXPECT_NE(referenceProblem(reference, resized).find("render size changed"), std::string::npos);
  LaneFrame filtered = flatFrame(4, 1, 0.1, 1.0f);
  filtered.settings.filter = FilterType::Gaussian;
  EXPECT_NE(referenceProblem(reference, filtered).find("pixel filter"), std::string::npos);
  LaneFrame otherScene = flatFrame(5, 1, 0.1, 1.0f);
  otherScene.scenePath = "other.gltf";
  EXPECT_NE(referenceProblem(reference, otherScene).find("another scene"), std::string::npos);
  LaneFrame resizedLights = flatFrame(5, 1, 0.1, 1.0f);
  resizedLights.sceneContent += 1;  // the same file loaded with another light size
  EXPECT_NE(referenceProblem(reference, resizedLights).find("the scene changed"),
            std::string::npos);

  // Parameters: a longer AO ray changes the expected image, more AO rays per sample do not.
  const std::vector<OptionSpec> aoParams = {
      OptionSpec::integer("ao-rays", 4, 1, 64, "").keepingTheExpectedImage(),
      OptionSpec::real("ao-distance", 0.25, 0.0, 10.0, "")};
  LaneFrame ao = flatFrame(6, 1, 0.1, 1.0f);
  ao.params = ParamValues(aoParams);
  const ReferenceImage aoReference = flatReference(ao, 1.0f);
  ao.params.set("test", "ao-rays", 16);
  EXPECT_EQ(referenceProblem(aoReference, ao), "");
  ao.params.set("test", "ao-distance", 0.5);
  EXPECT_NE(referenceProblem(aoReference, ao).find("ao-distance=0.5 (not 0.25)"), std::string::npos)
      << referenceProblem(aoReference, ao);

  ErrorHistory history;
  history.add(moved, reference);
  EXPECT_TRUE(history.points().empty());
  EXPECT_NE(history.message().find("stale"), std::string::npos);
}

TEST(ErrorHistory, AReferenceWithThePanesRandomNumbersIsRefused) {
  LaneFrame frame = flatFrame(1, 1, 0.1, 1.0f);
  frame.settings.seed = 5;
  ReferenceImage reference = flatReference(frame, 1.0f, true);
  reference.seed = 5;
  reference.sampler = frame.settings.sampler;
  EXPECT_NE(referenceProblem(reference, frame).find("another --seed"), std::string::npos);
  reference.sampler = SamplerType::Sobol;  // other numbers from the same seed
  EXPECT_EQ(referenceProblem(reference, frame), "");
  reference.seed = 6;
  reference.sampler = frame.settings.sampler;
  EXPECT_EQ(referenceProblem(reference, frame), "");
}

TEST(ErrorPlot, LogAxesCoverWholeDecades) {
  const LogAxis axis = logAxis(0.003, 0.2);
  EXPECT_EQ(axis.first, -3);
  EXPECT_EQ(axis.last, 0);
  EXPECT_DOUBLE_EQ(axis.position(1e-3), 0.0);
  EXPECT_DOUBLE_EQ(axis.position(1.0), 1.0);
  EXPECT_NEAR(axis.position(0.01), 1.0 / 3.0, 1e-12);
  const LogAxis one = logAxis(0.1, 0.1);  // a single value still gets a decade
  EXPECT_EQ(one.last - one.first, 1);
  EXPECT_EQ(decadeLabel(0), "1");
  EXPECT_EQ(decadeLabel(2), "100");
  EXPECT_EQ(decadeLabel(-1), "0.1");
  EXPECT_EQ(decadeLabel(-2), "0.01");
  EXPECT_EQ(decadeLabel(-5), "1e-5");
  EXPECT_EQ(secondsLabel(-2), "10 ms");
  EXPECT_EQ(secondsLabel(0), "1 s");
  EXPECT_EQ(secondsLabel(2), "100 s");
}

// ---- References: from a file, made on demand ----

class ErrorPlotFiles : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder("pathway_error_plot"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

TEST_F(ErrorPlotFiles, LoadsAnExrAndRefusesWhatItCannotUse) {
  FilmImages images;
  images.color = Image(6, 4);
  for (Color& pixel : images.color.pixels) pixel = Color(0.25f);
  RenderMetadata made;
  made.integrator = "stage5@ref";
  made.spp = 4096;
  made.filter = FilterType::Tent;
  made.filterRadius = 1.0f;
  made.seed = 7;
  made.sampler = SamplerType::Sobol;
  writeImageFile(path("ref.exr"), images, made, 0.0f);
  const ReferenceView view{"scene.gltf", 0, CameraPose{}, FilterType::Box, 0.5f, {}};
  const ReferenceImage reference = loadReference(path("ref.exr"), view);
  EXPECT_EQ(reference.image.width, 6);
  EXPECT_EQ(reference.image.height, 4);
  EXPECT_FLOAT_EQ(reference.image.pixels[0].y, 0.25f);
  EXPECT_TRUE(reference.fromFile);
  EXPECT_EQ(reference.source, path("ref.exr") + " (stage5@ref, 4096 spp)");
  EXPECT_EQ(reference.view.filter, FilterType::Tent);  // the file says how it was filtered
  EXPECT_FLOAT_EQ(reference.view.filterRadius, 1.0f);
  EXPECT_EQ(reference.seed, 7u);
  EXPECT_EQ(reference.sampler, SamplerType::Sobol);

  auto refusal = [&](const std::string& file) {
    try {
      loadReference(file, view);
    } catch (const PathwayError& error) {
      return std::string(error.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal(path("missing.exr")).find(path("missing.exr")), std::string::npos);
  std::FILE* junk = std::fopen(path("junk.exr").c_str(), "w");
  std::fputs("not an image", junk);
  std::fclose(junk);
  EXPECT_NE(refusal(path("junk.exr")).find(path("junk.exr")), std::string::npos);
  writeImageFile(path("ref.png"), images, {}, 0.0f);
  EXPECT_NE(refusal(path("ref.png")).find("must be an EXR"), std::string::npos);
}

// A real render against its stage's reference: the error falls as the samples grow.
class ErrorPlotRender : public ::testing::Test {
 protected:
  static constexpr const char* kIntegrator = "stage5@ref";

  void SetUp() override {
    if (!registered(kIntegrator)) GTEST_SKIP() << "needs the stage 5 reference";
    auto scene = std::make_shared<LoadedScene>();
    scene->scene = test::smallLight(0.3f);
    scene->tracer = std::make_unique<RayTracer>(scene->scene);
    scene_ = scene;
  }

  // The frames the render worker would publish after `spps` samples per pixel, 1 per pass.
  std::vector<std::shared_ptr<const LaneFrame>> frames(std::vector<uint32_t> spps) const {
    const RenderRecipe recipe = RecipeBuilder(kIntegrator)
                                    .size(24, 16)
                                    .spp(spps.back(), 1)
                                    .sampler(SamplerType::Independent)
                                    .seed(3);
    const CameraPose pose = OrbitCamera(scene_->scene).pose();
    const Camera camera(pose.position, pose.lookAt, pose.up, pose.yfov, recipe.settings.width,
                        recipe.settings.height);
    RenderSession session(*scene_->tracer, camera, recipe);
    std::vector<std::shared_ptr<const LaneFrame>> result;
    for (uint32_t spp : spps) {
      while (session.renderer().stats().samplesPerPixel < spp) session.renderer().renderPass();
      auto frame = std::make_shared<LaneFrame>();
      RenderResult developed = session.develop();
      frame->job = 1;
      frame->scenePath = scene_->scene.sourcePath;
      frame->camera = pose;
      frame->integrator = session.integrator().name;
      frame->params = session.recipe().params;
      frame->settings = session.renderer().settings();
      frame->images = std::move(developed.images);
      frame->stats = developed.stats;
      result.push_back(frame);
    }
    return result;
  }

  std::shared_ptr<const LoadedScene> scene_;
};

TEST_F(ErrorPlotRender, ErrorFallsAsSamplesGrow) {
  const auto shown = frames({1, 4, 16});
  const std::optional<RenderResult> made = renderStageReference(*shown[0], *scene_, 1024, 64);
  ASSERT_TRUE(made);
  ReferenceImage reference;
  reference.image = made->images.color;
  reference.view = viewOf(*shown[0]);
  ErrorHistory history;
  for (const auto& frame : shown) history.add(*frame, reference);
  ASSERT_EQ(history.points().size(), 3u) << history.message();
  const double e1 = history.points()[0].relMse, e4 = history.points()[1].relMse,
               e16 = history.points()[2].relMse;
  // Monte Carlo: relMSE ∝ 1/spp (here 9.9e-4, 2.5e-4, 7.0e-5), plus the reference's own 1/1024.
  EXPECT_LT(e4, e1 / 2) << e1 << " " << e4;
  EXPECT_LT(e16, e4 / 2) << e4 << " " << e16;
  EXPECT_LT(e16, e1 / 8) << e1 << " " << e16;
  // Fixed seeds: the same numbers every time.
  ErrorHistory again;
  again.add(*frames({1})[0], reference);
  EXPECT_EQ(again.points()[0].relMse, e1);
}

TEST_F(ErrorPlotRender, MakesAReferenceInTheBackground) {
  const auto shown = frames({2});
  ReferenceMaker maker;
  maker.start(shown[0], scene_, 64);
  // The reference's fastest version: stage5@fast (render/wavefront.h).
  const std::string reference5 = referenceIntegratorName(5, ReferenceTracing::Fastest);
  EXPECT_EQ(maker.integrator(), reference5);
  EXPECT_EQ(maker.sppTarget(), 64u);
  std::optional<ReferenceImage> reference;
  for (int i = 0; i < 6000 && !reference; ++i) {
    reference = maker.take();
    if (!reference) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_TRUE(reference) << maker.error();
  EXPECT_FALSE(maker.running());
  EXPECT_EQ(maker.sppDone(), 64u);
  EXPECT_EQ(reference->source, reference5 + ", 64 spp");
  EXPECT_FALSE(reference->fromFile);
  EXPECT_EQ(reference->image.width, 24);
  EXPECT_EQ(referenceProblem(*reference, *shown[0]), "");  // made for this very view
  ErrorHistory history;
  history.add(*shown[0], *reference);
  EXPECT_EQ(history.points().size(), 1u);
}

TEST_F(ErrorPlotRender, CancelsAReferenceAtOnce) {
  const auto shown = frames({1});
  ReferenceMaker maker;
  maker.start(shown[0], scene_, setting::kReferenceSamplesPerPixel.maxValue);  // hours
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  EXPECT_TRUE(maker.running());
  const auto start = std::chrono::steady_clock::now();
  maker.cancel();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  EXPECT_FALSE(maker.running());
  EXPECT_FALSE(maker.take());
}

TEST(ReferenceMaker, SaysWhenTheStageHasNoReference) {
  auto frame = std::make_shared<LaneFrame>(flatFrame(1, 1, 0.1, 1.0f));
  frame->integrator = "stage9";  // not built in
  ReferenceMaker maker;
  maker.start(frame, nullptr, 64);
  EXPECT_FALSE(maker.running());
  EXPECT_NE(maker.error().find("no reference of stage9"), std::string::npos) << maker.error();
}

// ---- `pathway view --reference` end to end, headless ----

using Outcome = test::CommandOutcome;
const auto run = test::runCommand;

const std::string kScene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";
// As in viewer_test.cpp: no leak checks for the GL processes under the sanitizer build.
const std::string kEnv = "env ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 ";
const std::string kBinary = std::string(PATHWAY_BINARY);
const std::string kView = kEnv + kBinary + " view " + kScene +
                          " --headless --window-width 800 --window-height 600 --frames 20";

TEST_F(ErrorPlotFiles, HeadlessViewerPlotsAgainstAReferenceFile) {
  // Another seed than the viewer's: the panes must not repeat the reference's own samples.
  const Outcome made = run(kBinary + " render " + kScene + " -i stage1 --spp 16 --seed 1 " +
                           "--width 48 --height 32 -q -o " + path("ref.exr"));
  ASSERT_EQ(made.exitCode, 0) << made.output;
  const Outcome outcome = run(kView + " -i stage1 --split stage1 --width 48 --height 32 " +
                              "--reference " + path("ref.exr") + " --screenshot " + path("ui.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_TRUE(fs::exists(path("ui.png")));
  // Both panes measured, in the reference's view.
  EXPECT_EQ(outcome.output.find("not measured"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("error plot, left stage1: relMSE "), std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("error plot, right stage1: relMSE "), std::string::npos)
      << outcome.output;
}

TEST_F(ErrorPlotFiles, HeadlessViewerExplainsAReferenceOfAnotherSize) {
  const Outcome made = run(kBinary + " render " + kScene + " -i stage1 --spp 4 --width 48 " +
                           "--height 32 -q -o " + path("ref.exr"));
  ASSERT_EQ(made.exitCode, 0) << made.output;
  const Outcome outcome = run(kView + " --width 40 --height 30 --reference " + path("ref.exr") +
                              " --screenshot " + path("ui.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;  // a message in the panel, not a crash
  EXPECT_NE(outcome.output.find("--width 48 --height 32"), std::string::npos) << outcome.output;
}

TEST_F(ErrorPlotFiles, MissingReferenceFileStopsTheViewerAtOnce) {
  const Outcome outcome =
      run(kView + " --reference " + path("nowhere.exr") + " --screenshot " + path("ui.png"));
  EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
  EXPECT_NE(outcome.output.find(path("nowhere.exr")), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(path("ui.png")));
}

TEST_F(ErrorPlotFiles, HeadlessViewerMakesAReferenceOnDemand) {
  if (!registered("stage2@ref")) GTEST_SKIP() << "needs the stage 2 reference";
  const Outcome outcome = run(kView + " -i stage2@ref --width 48 --height 32 --make-reference " +
                              "--reference-spp 32 --screenshot " + path("ui.png"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("error plot, stage2@ref: relMSE "), std::string::npos)
      << outcome.output;
  EXPECT_EQ(outcome.output.find("not measured"), std::string::npos) << outcome.output;
}

}  // namespace
}  // namespace pathway

#endif  // PATHWAY_HAS_VIEWER
