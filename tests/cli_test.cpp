// End-to-end tests of `pathway render`: bad input gets one clear message, a non-zero exit and no
// output file; a good render writes its images with the settings and counters in the metadata.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>

#include "io/image_io.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

using Outcome = test::CommandOutcome;

Outcome runPathway(const std::string& arguments) {
  return test::runCommand(std::string(PATHWAY_BINARY) + " " + arguments);
}

class Cli : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder("pathway_cli"); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  // The command fails with exit code 1, prints one "pathway: error:" line naming `needle`, and
  // leaves no file behind.
  void expectRefused(const std::string& arguments, const std::string& needle) {
    const Outcome outcome = runPathway(arguments + " -o " + path("out.png"));
    EXPECT_NE(outcome.exitCode, 0) << arguments;
    EXPECT_NE(outcome.output.find(needle), std::string::npos)
        << arguments << "\nmessage was: " << outcome.output;
    EXPECT_TRUE(fs::is_empty(dir_)) << arguments << " left a file behind";
  }

  fs::path dir_;
};

const std::string kScene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";

// OpenImageIO's ~250 libraries are loaded only when an image is read or written
// (framework/io/raster.h), and libOSMesa with libLLVM only by the offscreen viewer
// (framework/viewer/osmesa_library.h): the program must not link them, or every command pays
// ~0.2 s and ~15 ms.
TEST(CliStartUp, TheProgramDoesNotLinkTheImageOrOffscreenGlLibraries) {
  const Outcome outcome = test::runCommand("ldd " PATHWAY_BINARY);
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  for (const char* library : {"OpenImageIO", "opencv", "OSMesa", "LLVM"})
    EXPECT_EQ(outcome.output.find(library), std::string::npos) << library << "\n" << outcome.output;
}

TEST_F(Cli, MissingSceneFileIsNamed) {
  expectRefused("render " + path("nowhere.gltf"), "nowhere.gltf");
}

TEST_F(Cli, MalformedSceneIsNamed) {
  std::FILE* file = std::fopen(path("broken.gltf").c_str(), "w");
  std::fputs("{\"asset\": {\"version\": \"2.0\"}, \"meshes\": [", file);
  std::fclose(file);
  const Outcome outcome = runPathway("render " + path("broken.gltf") + " -o " + path("out.png"));
  EXPECT_EQ(outcome.exitCode, 1);
  EXPECT_NE(outcome.output.find("broken.gltf"), std::string::npos) << outcome.output;
  EXPECT_FALSE(fs::exists(path("out.png")));
}

TEST_F(Cli, UnknownIntegratorListsTheKnownOnes) {
  expectRefused("render " + kScene + " --integrator stage9", "unknown integrator 'stage9'");
  expectRefused("render " + kScene + " --integrator stage9", "stage1");
}

TEST_F(Cli, UnknownParameterIsNamed) {
  expectRefused("render " + kScene + " -p bounces=3", "no parameter 'bounces'");
  expectRefused("render " + kScene + " -p bounces", "name=value");
}

TEST_F(Cli, ParametersAreReadByTheirKind) {
  // A switch is on/off, a choice takes its options' names; numbers for them are refused.
  expectRefused("render " + kScene + " -i stage5 -p nee=2", "on or off");
  expectRefused("render " + kScene + " -i stage5 -p light-pick=1", "area or power");
  expectRefused("render " + kScene + " -i stage2 -p ao-rays=5000", "[1, 1024]");
  const Outcome outcome =
      runPathway("render " + kScene + " -i stage5 -p nee=off -p light-pick=area --width 8 " +
                 "--height 8 --spp 1 -q -o " + path("a.exr"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_EQ(readImageFile(path("a.exr")).metadata.params,
            "max-depth=5 rr-depth=3 nee=off light-pick=area");
}

TEST_F(Cli, EarlierStagesCanComeFromTheReference) {
  expectRefused("render " + kScene + " -i stage3 --earlier-stages theirs", "own or reference");
  const Outcome outcome =
      runPathway("render " + kScene + " -i stage3 --earlier-stages reference --width 8 " +
                 "--height 8 --spp 1 -q -o " + path("a.exr"));
  if (test::haveReference()) {
    ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
    EXPECT_EQ(readImageFile(path("a.exr")).metadata.earlierStages, "reference");
  } else {
    // Without reference stages the message says which one is missing, and why.
    EXPECT_EQ(outcome.exitCode, 1);
    EXPECT_NE(outcome.output.find("the reference stage"), std::string::npos) << outcome.output;
    EXPECT_NE(outcome.output.find("is not available"), std::string::npos) << outcome.output;
  }
}

TEST_F(Cli, LampsAreIgnoredWithAWarningUnlessStrict) {
  const std::string lamp = std::string(PATHWAY_TEST_DATA_DIR) + "/gltf/required_lamp.gltf";
  const Outcome loose =
      runPathway("render " + lamp + " --width 8 --height 8 --spp 1 -q -o " + path("a.png"));
  EXPECT_EQ(loose.exitCode, 0) << loose.output;
  EXPECT_NE(loose.output.find("warning"), std::string::npos) << loose.output;
  EXPECT_NE(loose.output.find("emissive meshes"), std::string::npos) << loose.output;
  fs::remove(path("a.png"));
  expectRefused("render " + lamp + " --strict", "KHR_lights_punctual");
}

TEST_F(Cli, OutOfRangeSettingsAreRefused) {
  expectRefused("render " + kScene + " --spp 0", "--spp");
  expectRefused("render " + kScene + " --width -5", "--width");
  expectRefused("render " + kScene + " --filter-radius 100", "--filter-radius");
  expectRefused("render " + kScene + " --sampler halton", "halton");
  expectRefused("render " + kScene + " --filter sinc", "sinc");
}

TEST_F(Cli, AGradeOptionWithoutItsModeIsRefused) {
  const Outcome outcome = runPathway("grade --verdict-seeds --stage 1");
  EXPECT_EQ(outcome.exitCode, 1);
  EXPECT_NE(outcome.output.find("--verdict-seeds goes with --calibrate"), std::string::npos)
      << outcome.output;
}

TEST_F(Cli, BadOutputPathIsRefusedBeforeRendering) {
  const Outcome jpg = runPathway("render " + kScene + " -o " + path("out.jpg"));
  EXPECT_EQ(jpg.exitCode, 1);
  EXPECT_NE(jpg.output.find("out.jpg"), std::string::npos) << jpg.output;
  const Outcome folder = runPathway("render " + kScene + " -o " + path("missing/out.png"));
  EXPECT_EQ(folder.exitCode, 1);
  EXPECT_NE(folder.output.find("does not exist"), std::string::npos) << folder.output;
  EXPECT_TRUE(fs::is_empty(dir_));
}

TEST_F(Cli, RenderWritesPngAndExrWithSettingsAndCounters) {
  const Outcome outcome =
      runPathway("render " + kScene + " -i stage1 --spp 3 --width 40 --height 30 --seed 5 -q -o " +
                 path("a.png") + " -o " + path("a.exr"));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_TRUE(fs::exists(path("a.png")));
  const LoadedImage exr = readImageFile(path("a.exr"));
  EXPECT_EQ(exr.images.color.width, 40);
  EXPECT_EQ(exr.images.color.height, 30);
  EXPECT_EQ(exr.images.variance.width, 40);
  EXPECT_EQ(exr.images.weight.width, 40);
  EXPECT_EQ(exr.metadata.integrator, "stage1");
  EXPECT_EQ(exr.metadata.spp, 3u);
  EXPECT_EQ(exr.metadata.seed, 5u);
  EXPECT_EQ(exr.metadata.primaryRays, 40u * 30 * 3);
  // The student skeleton of stage 1 is unfinished: the render says so and records it. (In a
  // handout assignments/ holds the student's own work, finished or not.)
  if (test::kFullRepository) {
    EXPECT_NE(outcome.output.find("assignments/stage1/stage1_filtering.cpp"), std::string::npos)
        << outcome.output;
    EXPECT_GT(exr.metadata.todos, 0);
  }
  // No temporary files are left next to the outputs.
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_)) ++files;
  EXPECT_EQ(files, 2u);
}

// Every student stage is there: the program loads each from its own library
// (stage_loading/student_stages.h), which finds every stage API function in the program (in a
// handout too, where no built-in stage calls them) and nothing else.
TEST_F(Cli, ListDescribesEveryIntegrator) {
  const Outcome outcome = runPathway("render --list");
  EXPECT_EQ(outcome.exitCode, 0);
  for (int stage = 1; stage <= 5; ++stage)
    EXPECT_NE(outcome.output.find("stage" + std::to_string(stage) + "       stage " +
                                  std::to_string(stage) + ", student"),
              std::string::npos)
        << outcome.output;
  EXPECT_EQ(outcome.output.find("cannot be loaded"), std::string::npos) << outcome.output;
  if (test::haveReference()) {
    EXPECT_NE(outcome.output.find("stage1@ref"), std::string::npos) << outcome.output;
  }
}

}  // namespace
}  // namespace pathway
