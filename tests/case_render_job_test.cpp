// The grader's child command line (grade/case_render_job.h): what the parent writes, the child
// reads back as the same job (paths with spaces, several cases, exact time limits); anything else
// is refused with one message that names the argument; and the program runs a job from it.
#include "grade/case_render_job.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

CaseRenderJob sampleJob() {
  CaseRenderJob job;
  const std::vector<GradingCase>& cases = gradingCases();
  job.cases = {{&cases.at(0), 15.0}, {&cases.at(3), 17.123456789}, {&cases.back(), 120.0}};
  job.output = "/tmp/a grading folder/work";
  job.scenes = "/srv/course files/scenes";
  job.seed = 18446744073709551615ull;  // the largest seed
  job.together = true;
  job.gradeReference = true;
  job.stageLibraries = {"/home/a student/build/stage1.so", "/home/a student/build/stage 2.so"};
  job.referenceStages = {1, 2};
  job.referenceFolder = "/srv/course files/reference";
  job.reportsSandbox = true;
  job.warpTestStage = 5;
  return job;
}

// The message of the PathwayError that parsing `arguments` throws ("" when it throws none).
std::string refusal(const std::vector<std::string>& arguments) {
  try {
    CaseRenderJob::fromArguments(arguments);
  } catch (const PathwayError& error) {
    return error.what();
  }
  return "";
}

// sampleJob()'s command line with `from`..`to` (word indices) replaced by `words`.
std::vector<std::string> edited(size_t from, size_t to, const std::vector<std::string>& words) {
  std::vector<std::string> arguments = sampleJob().toArguments();
  arguments.erase(arguments.begin() + from, arguments.begin() + to);
  arguments.insert(arguments.begin() + from, words.begin(), words.end());
  return arguments;
}

TEST(CaseRenderJob, ItsCommandLineReadsBackAsTheSameJob) {
  const CaseRenderJob job = sampleJob();
  const std::vector<std::string> arguments = job.toArguments();
  EXPECT_EQ(arguments.front(), CaseRenderJob::kCommand);
  EXPECT_EQ(CaseRenderJob::fromArguments(arguments), job);
  // Without the switches and libraries, with one case.
  CaseRenderJob plain;
  plain.cases = {{&gradingCases().at(1), 30.5}};
  plain.output = "out";
  plain.scenes = "scenes";
  EXPECT_EQ(CaseRenderJob::fromArguments(plain.toArguments()), plain);
  EXPECT_FALSE(CaseRenderJob::fromArguments(plain.toArguments()) == job);
  // Where the child's render goes: the parent looks for it there.
  EXPECT_EQ(
      job.imagePath(*job.cases[1].gradingCase),
      "/tmp/a grading folder/work/" + job.cases[1].gradingCase->id() + "-18446744073709551615.exr");
  // The warp test alone, with no case: its outcome goes beside the renders.
  CaseRenderJob warp = plain;
  warp.cases.clear();
  warp.warpTestStage = 2;
  EXPECT_EQ(CaseRenderJob::fromArguments(warp.toArguments()), warp);
  EXPECT_EQ(job.warpTestPath(),
            "/tmp/a grading folder/work/warptest-stage5-18446744073709551615.txt");
}

// A child grading a student's stage N holds the reference's stages below N at most; one grading
// the reference itself, stages 1..N; one grading the student's stages together, none.
TEST(CaseRenderJob, AChildHoldsNoReferenceOfTheStageItGradesOrALaterOne) {
  EXPECT_EQ(CaseRenderJob::referenceStagesFor(1, false, false), std::vector<int>{});
  EXPECT_EQ(CaseRenderJob::referenceStagesFor(3, false, false), (std::vector<int>{1, 2}));
  EXPECT_EQ(CaseRenderJob::referenceStagesFor(5, false, true), std::vector<int>{});
  EXPECT_EQ(CaseRenderJob::referenceStagesFor(3, true, false), (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(CaseRenderJob::referenceStagesFor(2, true, true), (std::vector<int>{1, 2}));
  const std::string command = CaseRenderJob::kCommand;
  std::vector<std::string> arguments = sampleJob().toArguments();
  const auto stageAt = std::find(arguments.begin(), arguments.end(), "--reference-stage");
  ASSERT_NE(stageAt, arguments.end());
  *(stageAt + 1) = "6";
  EXPECT_EQ(refusal(arguments), command + ": --reference-stage '6' is not a stage (1 to 5)");
  arguments = sampleJob().toArguments();
  const auto folderAt = std::find(arguments.begin(), arguments.end(), "--reference-folder");
  ASSERT_NE(folderAt, arguments.end());
  arguments.erase(folderAt, folderAt + 2);
  EXPECT_EQ(refusal(arguments), command + ": --reference-stage needs a --reference-folder");
}

TEST(CaseRenderJob, AnythingElseIsRefusedNamingWhat) {
  const std::vector<std::string> arguments = sampleJob().toArguments();
  ASSERT_EQ(arguments[7], "--case");  // after the command, --output, --scenes and --seed
  ASSERT_EQ(arguments[9], "--time-limit");
  const std::string command = CaseRenderJob::kCommand;
  // An unknown flag, and a flag of `pathway grade` that is not the child's.
  EXPECT_EQ(refusal(edited(1, 1, {"--bogus"})), command + ": unknown argument '--bogus'");
  EXPECT_EQ(refusal(edited(1, 1, {"--render-case"})),
            command + ": unknown argument '--render-case'");
  // A value missing at the end, or empty.
  std::vector<std::string> truncated = arguments;
  truncated.push_back("--stages-library");
  EXPECT_EQ(refusal(truncated), command + ": --stages-library needs a value");
  EXPECT_EQ(refusal(edited(2, 3, {""})), command + ": --output needs a value");
  // A time limit or seed that is not a number.
  EXPECT_EQ(refusal(edited(10, 11, {"fast"})),
            command + ": --time-limit 'fast' is not a positive number of seconds");
  EXPECT_EQ(refusal(edited(10, 11, {"15s"})),
            command + ": --time-limit '15s' is not a positive number of seconds");
  EXPECT_EQ(refusal(edited(10, 11, {"0"})),
            command + ": --time-limit '0' is not a positive number of seconds");
  EXPECT_EQ(refusal(edited(10, 11, {"nan"})),
            command + ": --time-limit 'nan' is not a positive number of seconds");
  EXPECT_EQ(refusal(edited(6, 7, {"-1"})),
            command + ": --seed '-1' is not a seed (a whole number from 0)");
  // An unknown case, named with the known ones.
  const std::string unknown = refusal(edited(8, 9, {"stage9-nowhere"}));
  EXPECT_EQ(unknown.rfind(command + ": --case: unknown grading case 'stage9-nowhere' (known: ", 0),
            0u)
      << unknown;
  // A case without its time limit, a time limit without its case, an option given twice.
  EXPECT_EQ(
      refusal(edited(9, 11, {})),
      command + ": --case " + sampleJob().cases[0].gradingCase->id() + " has no --time-limit");
  EXPECT_EQ(refusal(edited(7, 9, {})), command + ": --time-limit must follow a --case of its own");
  EXPECT_EQ(refusal(edited(1, 1, {"--seed", "2"})), command + ": --seed is given twice");
  EXPECT_EQ(refusal(edited(1, 1, {"--together"})), command + ": --together is given twice");
  // What every job has.
  EXPECT_EQ(refusal(edited(1, 3, {})), command + ": no --output given");
  EXPECT_EQ(
      refusal({command, "--output", "o", "--scenes", "s", "--seed", "1", "--sandbox", "auto"}),
      command + ": no --case or --warp-test given");
  // A warp test of a stage that has none, or asked for twice.
  std::vector<std::string> warp = arguments;
  *(std::find(warp.begin(), warp.end(), "--warp-test") + 1) = "3";
  EXPECT_EQ(refusal(warp), command + ": --warp-test '3' is not a stage with a warp test (2 or 5)");
  EXPECT_EQ(refusal(edited(1, 1, {"--warp-test", "2"})), command + ": --warp-test is given twice");
  EXPECT_EQ(refusal({command, "--output", "o", "--scenes", "s", "--seed", "1"}),
            command + ": no --sandbox given");
  EXPECT_EQ(refusal(edited(0, 1, {"grade"})),
            command + ": the command line does not start with " + command);
}

TEST(CaseRenderJob, TheChildProgramHandsItsCommandLineToTheJob) {
  // Refused by the job's parser, in one line.
  const test::CommandOutcome refused = test::runCommand(
      std::string(PATHWAY_CHILD_BINARY) + " " + CaseRenderJob::kCommand + " --output o --bogus");
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.output.find("pathway: error: " + std::string(CaseRenderJob::kCommand) +
                                ": unknown argument '--bogus'"),
            std::string::npos)
      << refused.output;
  // The course's program has no such command: it holds the reference stages, so no student
  // code ever runs in it.
  const test::CommandOutcome program =
      test::runCommand(std::string(PATHWAY_BINARY) + " " + CaseRenderJob::kCommand + " --output o");
  EXPECT_NE(program.exitCode, 0) << program.output;
  const test::CommandOutcome help = test::runCommand(std::string(PATHWAY_BINARY) + " --help");
  EXPECT_EQ(help.output.find(CaseRenderJob::kCommand), std::string::npos) << help.output;

  // A job run by the program writes its render where imagePath says (a folder with a space).
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages";
  const fs::path folder = test::freshTestFolder("pathway_case_render_job") / "the renders";
  fs::create_directories(folder);
  CaseRenderJob job;
  job.cases = {{&gradingCases().at(0), 60.0}};
  job.output = folder.string();
  job.scenes = PATHWAY_SCENES_DIR;
  job.gradeReference = true;
  job.referenceStages =
      CaseRenderJob::referenceStagesFor(job.cases[0].gradingCase->stage, true, false);
  job.referenceFolder = PATHWAY_REFERENCE_LIBRARY_DIR;
  shareWithSandboxUser(folder.string(), job.sandbox);  // its child runs as nobody under root
  std::string command = PATHWAY_CHILD_BINARY;
  for (const std::string& argument : job.toArguments()) command += " '" + argument + "'";
  const test::CommandOutcome rendered = test::runCommand(command);
  EXPECT_EQ(rendered.exitCode, 0) << rendered.output;
  EXPECT_TRUE(fs::is_regular_file(job.imagePath(*job.cases[0].gradingCase))) << rendered.output;
  fs::remove_all(folder.parent_path());
}

}  // namespace
}  // namespace pathway
