// A class graded on one machine: six submissions (correct, a planted bug, one that does not
// compile, one that crashes, one that hangs, one with a missing file) each get their own result,
// and none stops the others. Stage 2 only, to keep the test short.
#include <gtest/gtest.h>

#include <filesystem>

#include "class_submissions.h"
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

}  // namespace
}  // namespace pathway
