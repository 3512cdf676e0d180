// Gradescope's autograder end to end, in a temporary folder laid out as Gradescope's /autograder
// (AUTOGRADER_ROOT): the zip from scripts/make-autograder, setup.sh (installs what is missing and
// builds the grader), and run_autograder for a correct submission, one with a planted bug, and
// one that does not compile.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/sandbox.h"
#include "grade_results.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// Extracts a zip keeping the files' modes, as Gradescope's unzip does.
const char* const kUnzip =
    "python3 -c 'import os,sys,zipfile\n"
    "z=zipfile.ZipFile(sys.argv[1])\n"
    "for i in z.infolist():\n"
    "  p=z.extract(i,sys.argv[2]); m=i.external_attr>>16\n"
    "  m and os.chmod(p,m&0o777)' ";

TEST(Gradescope, TheAutograderZipSetsUpAndGradesSubmissions) {
  if (!test::kFullRepository)
    GTEST_SKIP() << "needs solutions/ (the autograder is built from them)";
  if (test::runCommand("git -C " PATHWAY_SOURCE_DIR " rev-parse 2>&1").exitCode != 0)
    GTEST_SKIP() << "not a git checkout (make-autograder packs the files git tracks)";
  const fs::path root =
      fs::temp_directory_path() / ("pathway_gradescope_" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "source");
  const std::string zip = (root / "autograder.zip").string();
  const std::string env = "AUTOGRADER_ROOT=" + root.string() + " ";

  test::CommandOutcome step =
      test::runCommand(std::string(PATHWAY_SOURCE_DIR) + "/scripts/make-autograder " + zip);
  ASSERT_EQ(step.exitCode, 0) << step.output;
  step = test::runCommand(kUnzip + zip + " " + (root / "source").string());
  ASSERT_EQ(step.exitCode, 0) << step.output;
  ASSERT_TRUE(fs::exists(root / "source/setup.sh"));
  fs::copy_file(root / "source/run_autograder", root / "run_autograder");
  step = test::runCommand(env + "bash " + (root / "source/setup.sh").string());
  ASSERT_EQ(step.exitCode, 0) << step.output;

  auto submit = [&](const std::string& prepare) {
    fs::remove_all(root / "submission");
    fs::remove_all(root / "results");
    fs::create_directories(root / "submission");
    const std::string submission = (root / "submission").string();
    EXPECT_EQ(test::runCommand("cp " PATHWAY_SOURCE_DIR "/solutions/*/*.cpp " + submission +
                               " && " + prepare)
                  .exitCode,
              0);
    step = test::runCommand(env + (root / "run_autograder").string());
    EXPECT_EQ(step.exitCode, 0) << step.output;
    return test::readTextFile((root / "results/results.json").string());
  };

  const std::string correct = submit("true");
  EXPECT_EQ(test::score(correct), 100.0) << correct;
  // The student's code was shut in, and the results say how.
  const std::string sandbox = nlohmann::json::parse(correct).at("extra_data").at("sandbox");
  EXPECT_EQ(sandbox.rfind("compiler: sandbox require: files: Landlock", 0), 0u) << sandbox;
  EXPECT_NE(correct.find("renders: sandbox require: files: Landlock"), std::string::npos);
  if (::geteuid() == 0) {  // as the child found itself, after it shut itself in
    EXPECT_NE(correct.find("user: uid " + std::to_string(sandboxUser().uid) + " (not root)"),
              std::string::npos)
        << correct;
  }
  for (const auto& [name, status] : test::caseStatuses(correct))
    EXPECT_EQ(status, "passed") << name;
  EXPECT_TRUE(fs::exists(root / "results/report/index.html"));

  const std::string buggy = submit("sed -i 's/visibility \\* local.z/visibility/' " +
                                   (root / "submission/stage2_nested_ao.cpp").string());
  EXPECT_EQ(test::score(buggy), 80.0) << buggy;
  bool ceilingFound = false;
  for (const test::CaseLine& line : test::caseLines(buggy)) {
    if (line.name != "Stage 2 · ceiling") continue;
    ceilingFound = true;
    EXPECT_EQ(line.score, 0.0) << line.output;
  }
  EXPECT_TRUE(ceilingFound) << buggy;

  // A file that does not compile costs its own stage only.
  const std::string broken = submit("echo 'this is not C++' >> " +
                                    (root / "submission/stage4_naive_recursion.cpp").string());
  EXPECT_EQ(test::score(broken), 80.0) << broken;
  EXPECT_NE(broken.find("stage4_naive_recursion.cpp did not compile"), std::string::npos) << broken;
  EXPECT_NE(broken.find("this is not C++"), std::string::npos) << "the compiler's message";
  // The solutions' sources are gone from the image once the grader is built.
  EXPECT_FALSE(fs::exists(root / "source/solutions"));
  test::runCommand("chmod -R u+w " + root.string());
  fs::remove_all(root);
}

}  // namespace
}  // namespace pathway
