// `pathway cluster` with the local scheduler (no Slurm needed): a render split into tasks merges
// into the one-process render; a task that keeps failing is named with its log and the other
// tasks' parts stay; bad options are refused before any task runs. The same jobs on a real Slurm
// cluster: tests/slurm/.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "io/image_io.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kPathway = PATHWAY_BINARY;
const std::string kScene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";

// The largest difference between two images, relative to the first's pixel values.
double largestRelativeDifference(const Image& a, const Image& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::fabs(double(a.pixels[i][c]) - b.pixels[i][c]) /
                                  std::max(1e-30, std::fabs(double(a.pixels[i][c]))));
  return worst;
}

TEST(ClusterLocal, ARenderSplitIntoTasksEqualsOneRender) {
  const fs::path dir = test::freshTestFolder("pathway_cluster_local");
  const std::string render = kScene + " -i " + test::stage(5) + " --width 40 --filter mitchell";
  const test::CommandOutcome split =
      test::runCommand(kPathway + " cluster render -q --tasks 5 --workers 2 --spp 20 -o " +
                       (dir / "merged.exr").string() + " -- " + render);
  ASSERT_EQ(split.exitCode, 0) << split.output;
  ASSERT_EQ(test::runCommand(kPathway + " render -q " + render + " --spp 20 -o " +
                             (dir / "single.exr").string())
                .exitCode,
            0);
  const LoadedImage merged = readImageFile((dir / "merged.exr").string());
  const LoadedImage single = readImageFile((dir / "single.exr").string());
  // Only the order of the film's additions differs: equal to a float's rounding.
  EXPECT_LE(largestRelativeDifference(single.images.color, merged.images.color), 2.0 / (1 << 23));
  EXPECT_EQ(merged.metadata.sampleBegin, 0u);
  EXPECT_EQ(merged.metadata.sampleEnd, 20u);
  EXPECT_EQ(merged.metadata.primaryRays, single.metadata.primaryRays);
  EXPECT_EQ(merged.metadata.secondaryRays, single.metadata.secondaryRays);
  EXPECT_EQ(merged.metadata.shadowRays, single.metadata.shadowRays);
  EXPECT_EQ(merged.metadata.samples, single.metadata.samples);
  for (int task = 0; task < 5; ++task)
    EXPECT_TRUE(
        fs::exists(dir / "merged.cluster/logs" / ("task-" + std::to_string(task) + ".log")));
  fs::remove_all(dir);
}

TEST(ClusterLocal, ATaskThatKeepsFailingIsNamedAndTheOtherPartsStay) {
  const fs::path dir = test::freshTestFolder("pathway_cluster_local");
  // A folder where task 2's part should go: its render cannot write there, on both attempts.
  fs::create_directories(dir / "out.cluster/parts/part-0002.exr");
  const test::CommandOutcome outcome = test::runCommand(
      kPathway + " cluster render -q --tasks 4 --spp 8 -o " + (dir / "out.exr").string() + " -- " +
      kScene + " -i " + test::stage(1) + " --width 16");
  EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
  EXPECT_NE(outcome.output.find("task 2 exited with status 1"), std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("task-2.retry1.log) after 2 attempts"), std::string::npos)
      << outcome.output;
  EXPECT_NE(test::readTextFile((dir / "out.cluster/logs/task-2.log").string()).find("part-0002"),
            std::string::npos);
  EXPECT_NE(outcome.output.find("samples 4:6 are missing (task 2)"), std::string::npos)
      << outcome.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  for (const char* part : {"part-0000.exr", "part-0001.exr", "part-0003.exr"})
    EXPECT_TRUE(fs::is_regular_file(dir / "out.cluster/parts" / part)) << part;
  fs::remove_all(dir);
}

TEST(ClusterLocal, BadOptionsAreRefusedBeforeAnyTaskRuns) {
  const fs::path dir = test::freshTestFolder("pathway_cluster_local");
  const std::string out = " -o " + (dir / "out.exr").string() + " -- " + kScene;
  const test::CommandOutcome integrator =
      test::runCommand(kPathway + " cluster render --tasks 2 --spp 4" + out + " -i stage9");
  EXPECT_EQ(integrator.exitCode, 1);
  EXPECT_NE(integrator.output.find("stage9"), std::string::npos) << integrator.output;
  EXPECT_FALSE(fs::exists(dir / "out.cluster/logs/task-0.log"));
  const test::CommandOutcome tooMany =
      test::runCommand(kPathway + " cluster render --tasks 9 --spp 4" + out);
  EXPECT_EQ(tooMany.exitCode, 1);
  EXPECT_NE(tooMany.output.find("--tasks 9"), std::string::npos) << tooMany.output;
  // Asking for Slurm where there is none says so.
  const test::CommandOutcome noSlurm =
      test::runCommand("env PATH=/nonexistent " + kPathway +
                       " cluster render --scheduler slurm --tasks 2 --spp 4" + out);
  EXPECT_EQ(noSlurm.exitCode, 1);
  EXPECT_NE(noSlurm.output.find("sbatch was not found"), std::string::npos) << noSlurm.output;
  const test::CommandOutcome noClass =
      test::runCommand(kPathway + " cluster grade --submissions " + (dir / "nothing").string() +
                       " --output " + dir.string());
  EXPECT_EQ(noClass.exitCode, 1);
  EXPECT_NE(noClass.output.find("not a folder of submissions"), std::string::npos)
      << noClass.output;
  fs::create_directories(dir / "class/alice");
  const test::CommandOutcome badGradeOption =
      test::runCommand(kPathway + " cluster grade --submissions " + (dir / "class").string() +
                       " --output " + (dir / "graded").string() + " -- --stage 9");
  EXPECT_EQ(badGradeOption.exitCode, 1);
  EXPECT_NE(badGradeOption.output.find("the grade options were refused"), std::string::npos)
      << badGradeOption.output;
  EXPECT_FALSE(fs::exists(dir / "graded/cluster/logs/task-0.log"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pathway
