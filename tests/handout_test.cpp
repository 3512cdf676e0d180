// The student handout as a student gets it (scripts/make-handout --check): exported with the
// reference stages compiled and no solution code, unpacked into a fresh folder, built, its own
// suite passed and scripts/start run there without a display. Then its self-grade gives the
// verdict the autograder (`pathway grade --submission` here) gives, case by case: on the untouched
// skeletons, and on a submission with a wrong stage and one that does not compile, which costs
// only its own stage. Not part of the handout itself.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "grade/grading_cases.h"
#include "grade_results.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kSource = PATHWAY_SOURCE_DIR;

// The autograder's verdicts on `submission` (a folder of stage files), graded in this repository,
// on the cases a handout has: the course's own cases (which it grades too) are counted apart.
std::map<std::string, std::string> autograderVerdicts(const fs::path& submission,
                                                      const fs::path& output) {
  const test::CommandOutcome graded =
      test::runCommand(std::string(PATHWAY_BINARY) + " grade -q --submission " +
                       submission.string() + " --output " + output.string());
  EXPECT_NE(graded.exitCode, -1) << graded.output;
  std::map<std::string, std::string> verdicts =
      test::caseStatuses(test::readTextFile((output / "results.json").string()));
  size_t courseCases = 0;
  for (const GradingCase& c : gradingCases())
    if (c.courseOnly)
      courseCases += verdicts.erase("Stage " + std::to_string(c.stage) + " · " + c.name);
  EXPECT_GE(courseCases, 5u) << "the autograder grades the course's own cases too";
  return verdicts;
}

class Handout : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::kFullRepository) GTEST_SKIP() << "makes a handout: needs the full repository";
#ifdef PATHWAY_SANITIZED
    GTEST_SKIP() << "the handout is built with release flags: the release suite checks it";
#endif
    if (test::runCommand("git -C " + kSource + " rev-parse 2>&1").exitCode != 0)
      GTEST_SKIP() << "not a git checkout (make-handout packs the files git tracks)";
    dir_ = test::freshTestFolder("pathway_handout");
  }
  void TearDown() override {
    if (!dir_.empty()) fs::remove_all(dir_);
  }
  fs::path dir_;
};

TEST_F(Handout, ShipsTheReferenceCompiledBuildsPassesItsSuiteAndGradesAsTheAutograder) {
  const fs::path tarball = dir_ / "handout.tar.gz", unpacked = dir_ / "unpacked";
  const test::CommandOutcome made =
      test::runCommand(kSource + "/scripts/make-handout " + tarball.string() + " --check --keep " +
                       unpacked.string());
  ASSERT_EQ(made.exitCode, 0) << made.output;
  EXPECT_NE(made.output.find("solution lines searched"), std::string::npos) << made.output;
  EXPECT_NE(made.output.find("100% tests passed"), std::string::npos) << made.output;
  EXPECT_NE(made.output.find("reference stages: from "), std::string::npos) << made.output;
  const fs::path handout = unpacked / "pathway";

  // The tarball as shipped, the compiled library included, holds no line of solutions/.
  const test::CommandOutcome leaks = test::runCommand(
      "mkdir " + (dir_ / "shipped").string() + " && tar -xzf " + tarball.string() +
      " --strip-components=1 -C " + (dir_ / "shipped").string() + " && " + kSource +
      "/scripts/handout-leaks " + kSource + " " + (dir_ / "shipped").string());
  EXPECT_EQ(leaks.exitCode, 0) << leaks.output;
  EXPECT_NE(leaks.output.find(": 0 found"), std::string::npos) << leaks.output;

  // What it holds: the reference compiled, no solutions, the student's README.
  EXPECT_FALSE(fs::exists(handout / "solutions"));
  EXPECT_FALSE(fs::exists(handout / "bench"));
  for (int stage = 1; stage <= 5; ++stage)
    EXPECT_TRUE(fs::exists(handout / ("reference/stage" + std::to_string(stage) + ".so"))) << stage;
  const std::string readme = test::readTextFile((handout / "README.md").string());
  EXPECT_EQ(readme, test::readTextFile(kSource + "/docs/student-readme.md"));
  for (const char* instructors : {"make-handout", "make-autograder", "--calibrate",
                                  "--make-references", "cluster", "solutions/", "slides", "bench"})
    EXPECT_EQ(readme.find(instructors), std::string::npos) << instructors;

  // The untouched skeletons: the handout's self-grade (scripts/start wrote it) and the
  // autograder's, case by case.
  const std::map<std::string, std::string> selfGrade =
      test::caseStatuses(test::readTextFile((handout / "grade-report/results.json").string()));
  EXPECT_GE(selfGrade.size(), 15u);
  // The handout has neither the course's cases nor their references, and says how many there are.
  EXPECT_FALSE(fs::exists(handout / "framework/grade/course_cases.cpp"));
  EXPECT_FALSE(fs::exists(handout / "scenes/references/course"));
  size_t courseCases = 0;
  for (const GradingCase& c : gradingCases()) courseCases += c.courseOnly;
  EXPECT_NE(test::readTextFile((handout / "grade-report/results.json").string())
                .find("The course's autograder also grades " + std::to_string(courseCases) +
                      " cases of its own"),
            std::string::npos);
  EXPECT_EQ(selfGrade, autograderVerdicts(kSource + "/assignments", dir_ / "skeletons"));

  // A submission in the handout: finished stages, with a missing cos θ in stage 2 and a stage 4
  // that does not compile. scripts/build fails for stage 4 alone: the program and the other
  // stages build, the self-grade grades them and fails stage 4's cases with the compiler's
  // message, and rendering stage 4 says why it is not there.
  const fs::path submission = dir_ / "submission";
  fs::create_directories(submission);
  const test::CommandOutcome prepared = test::runCommand(
      "cp " + kSource + "/solutions/*/*.cpp " + submission.string() + " && sed -i " +
      "'s/visibility \\* local.z/visibility/' " + (submission / "stage2_nested_ao.cpp").string() +
      " && echo 'int unfinished = ;' >> " + (submission / "stage4_naive_recursion.cpp").string() +
      " && for f in " + submission.string() + "/*.cpp; do n=$(basename $f); " + "cp $f " +
      handout.string() + "/assignments/${n%%_*}/$n; done && cd " + handout.string() +
      " && { scripts/build >build.log 2>&1; echo \"build status $?\"; }");
  EXPECT_NE(prepared.output.find("build status 1"), std::string::npos) << prepared.output;
  const std::string buildLog = test::readTextFile((handout / "build.log").string());
  EXPECT_NE(buildLog.find("stage4_naive_recursion.cpp"), std::string::npos) << buildLog;
  for (const char* stage : {"stage1", "stage2", "stage3", "stage5"})
    EXPECT_TRUE(fs::exists(handout / "build/release/stages" / (std::string(stage) + ".so")))
        << stage << "\n"
        << buildLog;
  const std::string pathway = (handout / "build/release/pathway").string();
  const test::CommandOutcome stage4 =
      test::runCommand(pathway + " render " + (handout / "scenes/cornell_box.gltf").string() +
                       " -q -i stage4 --width 8 --spp 1 -o " + (dir_ / "stage4.png").string());
  EXPECT_NE(stage4.exitCode, 0);
  EXPECT_NE(stage4.output.find("your stage4 is not here: assignments/stage4/"), std::string::npos)
      << stage4.output;
  const test::CommandOutcome graded =
      test::runCommand("cd " + handout.string() + " && " + pathway + " grade -q --report " +
                       (dir_ / "self-grade").string());
  EXPECT_EQ(graded.exitCode, 1) << "stages fail: " << graded.output;
  const std::string selfGradeText = test::readTextFile((dir_ / "self-grade/results.json").string());
  EXPECT_NE(selfGradeText.find("stage4_naive_recursion.cpp did not compile"), std::string::npos);
  const std::map<std::string, std::string> selfGraded = test::caseStatuses(selfGradeText);
  ASSERT_GE(selfGraded.size(), 15u) << graded.output;
  for (const auto& [name, status] : selfGraded)
    EXPECT_EQ(status,
              name.rfind("Stage 2", 0) == 0 || name.rfind("Stage 4", 0) == 0 ? "failed" : "passed")
        << name;
  EXPECT_EQ(selfGraded, autograderVerdicts(submission, dir_ / "autograded"));
}

TEST(HandoutLeaks, ASolutionLineInTheHandoutIsFound) {
  if (!test::kFullRepository) GTEST_SKIP() << "needs solutions/";
  const fs::path tree = test::freshTestFolder("pathway_handout_leaks");
  fs::create_directories(tree / "docs");
  std::ofstream(tree / "docs/notes.md") << "Nothing of the solution here.\n";
  const std::string scan = kSource + "/scripts/handout-leaks " + kSource + " " + tree.string();
  EXPECT_EQ(test::runCommand(scan).exitCode, 0);
  fs::copy_file(kSource + "/solutions/stage3/stage3_ao_4d.cpp", tree / "docs/stage3.txt");
  const test::CommandOutcome leak = test::runCommand(scan);
  EXPECT_EQ(leak.exitCode, 1);
  EXPECT_NE(leak.output.find("docs/stage3.txt: holds a line of solutions/stage3/stage3_ao_4d.cpp"),
            std::string::npos)
      << leak.output;
  fs::remove_all(tree);
}

}  // namespace
}  // namespace pathway
