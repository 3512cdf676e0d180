// `pathway cluster --scheduler slurm` on a real single-node Slurm cluster, which ctest starts
// before these tests and stops after them, pass or fail (scripts/slurm-cluster; the fixture is in
// tests/CMakeLists.txt). Run by hand: scripts/slurm-cluster start DIR, then
// SLURM_CONF=DIR/slurm.conf.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <thread>

#include "../class_submissions.h"
#include "../run_command.h"
#include "../stage_under_test.h"
#include "io/image_io.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kPathway = PATHWAY_BINARY;
const std::string kScene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";

class SlurmCluster : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* conf = std::getenv("SLURM_CONF");
    ASSERT_TRUE(conf && fs::exists(conf))
        << "no cluster: ctest starts one for these tests (or scripts/slurm-cluster start DIR and "
           "SLURM_CONF=DIR/slurm.conf)";
    dir_ = test::freshTestFolder("pathway_slurm");
  }
  void TearDown() override { fs::remove_all(dir_); }

  // `pathway cluster render` on Slurm, and the same render in one process.
  std::string clusterRender(const std::string& options, const std::string& render) {
    return kPathway + " cluster render --scheduler slurm " + options + " -o " +
           (dir_ / "merged.exr").string() + " -- " + render;
  }
  void expectMergedEqualsSingle(const std::string& render, uint32_t spp) {
    ASSERT_EQ(test::runCommand(kPathway + " render -q " + render + " --spp " + std::to_string(spp) +
                               " -o " + (dir_ / "single.exr").string())
                  .exitCode,
              0);
    const LoadedImage merged = readImageFile((dir_ / "merged.exr").string());
    const LoadedImage single = readImageFile((dir_ / "single.exr").string());
    ASSERT_EQ(merged.images.color.pixels.size(), single.images.color.pixels.size());
    double worst = 0.0;
    for (size_t i = 0; i < merged.images.color.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c) {
        const double a = single.images.color.pixels[i][c], b = merged.images.color.pixels[i][c];
        worst = std::max(worst, std::fabs(a - b) / std::max(1e-30, std::fabs(a)));
      }
    // Only the order of the film's additions differs: equal to a float's rounding.
    EXPECT_LE(worst, 2.0 / (1 << 23));
    EXPECT_EQ(merged.metadata.primaryRays, single.metadata.primaryRays);
    EXPECT_EQ(merged.metadata.secondaryRays, single.metadata.secondaryRays);
    EXPECT_EQ(merged.metadata.shadowRays, single.metadata.shadowRays);
    EXPECT_EQ(merged.metadata.samples, single.metadata.samples);
  }

  fs::path dir_;
};

TEST_F(SlurmCluster, AnEightTaskRenderArrayMergesIntoTheSingleProcessRender) {
  const std::string render = kScene + " -i " + test::stage(5) + " --width 48 --filter tent";
  const test::CommandOutcome outcome =
      test::runCommand(clusterRender("--tasks 8 --spp 64", render));
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("(8 task(s)) and job"), std::string::npos) << outcome.output;
  EXPECT_NE(outcome.output.find("8 done, 0 running, 0 waiting, 0 failed"), std::string::npos)
      << outcome.output;
  expectMergedEqualsSingle(render, 64);
}

TEST_F(SlurmCluster, ATaskKilledMidRunIsReportedAndRunAgain) {
  // Four tasks of one to three seconds each (the skeleton's placeholder is cheaper); task 2's
  // render is killed once it runs.
  const std::string render = kScene + " -i " + test::stage(5) + " --width 128";
  auto job = std::async(std::launch::async, [&] {
    return test::runCommand(clusterRender("--tasks 4 --spp 384", render));
  });
  bool killed = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (!killed && std::chrono::steady_clock::now() < deadline) {
    // "[p]art": the pattern must not match this command's own shell.
    killed = test::runCommand("pkill -KILL -f 'samples 192:288 .*[p]art-0002.exr'").exitCode == 0;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const test::CommandOutcome outcome = job.get();
  ASSERT_TRUE(killed) << "task 2 was never seen running\n" << outcome.output;
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("task 2 exited with status 137: killed by signal 9"),
            std::string::npos)
      << outcome.output;
  EXPECT_NE(outcome.output.find("task 2 failed, then succeeded on attempt 2"), std::string::npos)
      << outcome.output;
  EXPECT_TRUE(fs::exists(dir_ / "merged.cluster/logs/task-2.retry1.log"));
  expectMergedEqualsSingle(render, 384);
}

TEST_F(SlurmCluster, AClassIsGradedAsAnArrayWithAVerdictForEachSubmission) {
  if (!test::kFullRepository) GTEST_SKIP() << "needs solutions/ (its class is made from them)";
  ASSERT_TRUE(test::makeTestClass(dir_ / "submissions"));
  const test::CommandOutcome outcome =
      test::runCommand(kPathway + " cluster grade --scheduler slurm --tasks 3 --submissions " +
                       (dir_ / "submissions").string() + " --output " + (dir_ / "out").string() +
                       " -- --stage 2 --time-limit 4");
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  EXPECT_NE(outcome.output.find("(3 task(s)) and job"), std::string::npos) << outcome.output;
  test::expectTestClassVerdicts(dir_ / "out");
  // The class table came from the dependent job.
  EXPECT_TRUE(fs::exists(dir_ / "out/cluster/logs/finish.log"));
}

}  // namespace
}  // namespace pathway
