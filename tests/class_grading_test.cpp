// A class graded on one machine: six submissions (correct, a planted bug, one that does not
// compile, one that crashes, one that hangs, one with a missing file) each get their own result,
// and none stops the others. Stage 2 only, to keep the test short.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "class_submissions.h"
#include "core/sandbox.h"
#include "grade_results.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

TEST(ClassGrading, EverySubmissionGetsItsOwnResult) {
  if (!test::kFullRepository) GTEST_SKIP() << "needs solutions/ (its class is made from them)";
  const fs::path root = test::freshTestFolder("pathway_class");
  ASSERT_TRUE(test::makeTestClass(root / "submissions"));
  const test::CommandOutcome outcome = test::runCommand(
      std::string(PATHWAY_BINARY) + " grade -q --stage 2 --time-limit 4 --submissions " +
      (root / "submissions").string() + " --output " + (root / "out").string());
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  test::expectTestClassVerdicts(root / "out");

  // The table can be written again from the results alone (a cluster job's last step), and a
  // submission without results is listed as such.
  fs::remove_all(root / "out/bob");
  const test::CommandOutcome table = test::runCommand(
      std::string(PATHWAY_BINARY) + " grade -q --submissions " + (root / "submissions").string() +
      " --output " + (root / "out").string() + " --table-only");
  ASSERT_EQ(table.exitCode, 0) << table.output;
  const std::string csv = test::readTextFile((root / "out/class.csv").string());
  EXPECT_NE(test::classRow(csv, "alice").find("\"alice\",20.0,20.0"), std::string::npos) << csv;
  EXPECT_NE(test::classRow(csv, "bob").find("not graded: no results"), std::string::npos) << csv;
  fs::remove_all(root);
}

// A root grader whose submission sits in a folder only root may enter and whose output is under a
// `mktemp -d` (0700): the compiler and the renders still run as nobody (the grader stages what
// they read) and the stage is graded, not failed as "did not compile".
TEST(ClassGrading, AsRootAClosedSubmissionAndAClosedOutputAreGradedAsNobody) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root changes user";
  if (!test::kFullRepository) GTEST_SKIP() << "needs solutions/ (a correct stage to grade)";
  if (!probeSandbox({}, SandboxMode::Auto).missing.empty())
    GTEST_SKIP() << "this kernel cannot shut student code in completely (--sandbox require)";
  const fs::path root = test::freshTestFolder("pathway_closed");
  fs::create_directories(root / "closed/submission");
  fs::permissions(root / "closed", fs::perms::owner_all);
  fs::copy_file(PATHWAY_SOURCE_DIR "/solutions/stage1/stage1_filtering.cpp",
                root / "closed/submission/stage1_filtering.cpp");
  const test::CommandOutcome made = test::runCommand("mktemp -d");
  const fs::path output = fs::path(made.output.substr(0, made.output.find('\n'))) / "out";
  ASSERT_EQ(fs::status(output.parent_path()).permissions() & fs::perms::all, fs::perms::owner_all);
  const test::CommandOutcome graded = test::runCommand(
      std::string(PATHWAY_BINARY) + " grade -q --stage 1 --sandbox require --submission " +
      (root / "closed/submission").string() + " --output " + output.string());
  const std::string results = test::readTextFile((output / "results.json").string());
  EXPECT_EQ(graded.exitCode, 0) << graded.output << results;
  EXPECT_EQ(results.find("did not compile"), std::string::npos) << results;
  EXPECT_NE(results.find("compiler: sandbox require"), std::string::npos) << results;
  EXPECT_NE(results.find("user: uid " + std::to_string(sandboxUser().uid) + " (not root)"),
            std::string::npos)
      << results;
  EXPECT_DOUBLE_EQ(test::score(results), 20.0) << results;
  fs::remove_all(output.parent_path());
  fs::remove_all(root);
}

}  // namespace
}  // namespace pathway
