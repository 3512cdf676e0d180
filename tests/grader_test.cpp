// `pathway grade` end to end: the reference stages pass (fixed fresh seeds, so never flaky), every
// planted bug of the mutant suite fails its stage while the harmless mutants pass, the untouched
// skeletons fail on their images, a stage that crashes or hangs fails only its own case, and bad
// input gets one message and a failed result. Output: results.json and an HTML report.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "grade/stage_grading.h"
#include "grade_results.h"
#include "io/image_io.h"
#include "mutant_list.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

using ResultLine = test::CaseLine;

class Grader : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder("pathway_grade"); }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `pathway grade <arguments>` with its report in the test's folder.
  test::CommandOutcome grade(const std::string& arguments) {
    return test::runCommand(std::string(PATHWAY_BINARY) + " grade -q --report " +
                            (dir_ / "report").string() + " " + arguments);
  }
  std::vector<ResultLine> results() {
    return test::caseLines(test::readTextFile((dir_ / "report/results.json").string()));
  }

  fs::path dir_;
};

TEST_F(Grader, TheReferenceStagesPassWithFreshSeeds) {
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages";
  const test::CommandOutcome outcome = grade("--grade-reference --seed 7");
  EXPECT_EQ(outcome.exitCode, 0) << outcome.output;
  const std::vector<ResultLine> lines = results();
  EXPECT_GE(lines.size(), 15u);  // every grading case
  for (const ResultLine& line : lines) {
    EXPECT_EQ(line.status, "passed") << line.output;
    EXPECT_EQ(line.image, "pass");
    // The noise note is like for like: the reference reads about 1 wherever its noise is
    // measured (from stage 2 on); over 1000 seeds per case it stayed within 0.64-1.42.
    if (line.name.rfind("Stage 1 ", 0) == 0) {
      EXPECT_EQ(line.noiseRatio, 0.0) << line.name;
    } else {
      EXPECT_GE(line.noiseRatio, 0.5) << line.name;
      EXPECT_LE(line.noiseRatio, 2.0) << line.name;
    }
    EXPECT_EQ(line.output.find("times as noisy"), std::string::npos) << line.output;
  }
  // The report has a page and, for a passing case, its image and the reference's: no maps and
  // no difference image, which would look like a failure.
  EXPECT_TRUE(fs::exists(dir_ / "report/index.html"));
  size_t pictures = 0;
  for ([[maybe_unused]] const auto& entry : fs::directory_iterator(dir_ / "report/images"))
    ++pictures;
  EXPECT_EQ(pictures, 2 * lines.size());
  const std::string page = test::readTextFile((dir_ / "report/index.html").string());
  EXPECT_NE(page.find("stage3-corner-image.png"), std::string::npos);
  EXPECT_EQ(page.find("stage3-corner-z.png"), std::string::npos);
  EXPECT_NE(page.find("worst tile p"), std::string::npos);
  EXPECT_NE(page.find("M rays/s"), std::string::npos);  // your speed beside the reference's
  // Beside the cases: the warp tests of stages 2 and 5, passed, with no points.
  const std::string json = test::readTextFile((dir_ / "report/results.json").string());
  EXPECT_EQ(test::checkStatuses(json),
            (std::map<std::string, std::string>{{"Stage 2 · warp test (no points)", "passed"},
                                                {"Stage 5 · warp test (no points)", "passed"}}));
  EXPECT_NE(page.find("Your sampling routines: warp tests (no points)"), std::string::npos);
}

TEST_F(Grader, TheUntouchedSkeletonsFailOnTheirImages) {
  // In a handout, assignments/ holds the student's own work, no longer the skeletons.
  if (!test::kFullRepository) GTEST_SKIP() << "needs the untouched skeletons";
  for (int stage = 1; stage <= 5; ++stage) {
    const test::CommandOutcome outcome = grade("--stage " + std::to_string(stage));
    EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
    for (const ResultLine& line : results()) {
      EXPECT_EQ(line.status, "failed") << "stage " << stage << ": " << line.output;
      // The image itself is wrong, not only the TODO that ran.
      EXPECT_EQ(line.image, "fail") << "stage " << stage << ": " << line.output;
      EXPECT_NE(line.output.find("TODO at assignments/stage"), std::string::npos) << line.output;
    }
  }
  // The skeletons' sampling routines fail their warp tests (stage 5's report is the last one).
  const std::string json = test::readTextFile((dir_ / "report/results.json").string());
  EXPECT_EQ(test::checkStatuses(json),
            (std::map<std::string, std::string>{{"Stage 5 · warp test (no points)", "failed"}}));
  EXPECT_NE(json.find("summed over the emitters"), std::string::npos) << json;
  // A failing case shows its maps and difference beside the two images.
  const std::string page = test::readTextFile((dir_ / "report/index.html").string());
  for (const char* picture : {"image", "reference", "z", "block-z", "difference"})
    EXPECT_NE(page.find(std::string("stage5-cornell-box-") + picture + ".png"), std::string::npos)
        << picture;
}

#ifdef PATHWAY_MUTANT_LIST
TEST_F(Grader, AWrongSamplingRoutineFailsItsWarpTestBesideTheCases) {
  const std::map<std::string, std::string> verdicts = {
      {"s2_uniform_directions", "your directions crowd towards the horizon"},
      {"s5_area_pdf_two_percent", "summed over the emitters, is 0.9804"}};
  for (const auto& [name, verdict] : verdicts) {
    std::string library;
    int stage = 0;
    for (const test::Mutant& mutant : test::mutants())
      if (mutant.name == name) library = mutant.library, stage = mutant.stage;
    ASSERT_FALSE(library.empty()) << name << " is not in " << PATHWAY_MUTANT_LIST;
    grade("--stages-library " + library + " --stage " + std::to_string(stage));
    const std::string json = test::readTextFile((dir_ / "report/results.json").string());
    const std::string check = "Stage " + std::to_string(stage) + " · warp test (no points)";
    EXPECT_EQ(test::checkStatuses(json), (std::map<std::string, std::string>{{check, "failed"}}))
        << name;
    EXPECT_NE(json.find(verdict), std::string::npos) << name << ": " << json;
    // No points for it: the score is the cases' alone.
    double cases = 0.0;
    for (const ResultLine& line : results()) cases += line.score;
    EXPECT_NEAR(test::score(json), cases, 1e-9) << name;
  }
}
#endif

TEST_F(Grader, BadInputGetsOneMessageAndAFailedResult) {
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages";
  // A reference folder with one reference missing, one truncated, one from another case.
  const fs::path references = dir_ / "references";
  fs::create_directories(references);
  const fs::path shipped = fs::path(PATHWAY_SCENES_DIR) / "references";
  fs::copy_file(shipped / "stage1-edges-tent.exr", references / "stage1-edges-gaussian.exr");
  const std::string whole = test::readTextFile((shipped / "stage1-edges-mitchell.exr").string());
  std::ofstream(references / "stage1-edges-mitchell.exr", std::ios::binary)
      << whole.substr(0, whole.size() / 3);
  const test::CommandOutcome outcome =
      grade("--grade-reference --stage 1 --references " + references.string());
  EXPECT_EQ(outcome.exitCode, 1) << outcome.output;
  const std::vector<ResultLine> lines = results();
  // Every case of stage 1 (and the course's own), in the order grading_cases.cpp declares them.
  ASSERT_EQ(lines.size(), gradingCasesOf(1).size());
  for (const ResultLine& line : lines) EXPECT_EQ(line.status, "failed");
  const auto outputOf = [&](const std::string& name) {
    for (const ResultLine& line : lines)
      if (line.name == name) return line.output;
    ADD_FAILURE() << "no result for " << name;
    return std::string();
  };
  EXPECT_NE(outputOf("Stage 1 · cornell-box").find("stage1-cornell-box.exr"), std::string::npos);
  EXPECT_NE(outputOf("Stage 1 · edges-mitchell").find("stage1-edges-mitchell.exr"),
            std::string::npos);
  EXPECT_NE(outputOf("Stage 1 · edges-gaussian").find("other settings"), std::string::npos);
  EXPECT_EQ(outcome.output.find("internal error"), std::string::npos) << outcome.output;

  // Two files of different sizes compared directly.
  const std::string a = (dir_ / "a.exr").string(), b = (dir_ / "b.exr").string();
  const std::string render = std::string(PATHWAY_BINARY) + " render " + PATHWAY_SCENES_DIR +
                             "/cornell_box.gltf -q --spp 2 -i stage1";
  ASSERT_EQ(test::runCommand(render + " --width 32 --height 32 -o " + a).exitCode, 0);
  ASSERT_EQ(test::runCommand(render + " --width 40 --height 32 -o " + b).exitCode, 0);
  const test::CommandOutcome sizes = grade("--image " + a + " --reference " + b);
  EXPECT_EQ(sizes.exitCode, 1);
  EXPECT_NE(results().at(0).output.find("32x32 pixels, the reference 40x32"), std::string::npos);
  const test::CommandOutcome missing = grade("--image " + a + " --reference " + b + ".nope");
  EXPECT_EQ(missing.exitCode, 1);
  EXPECT_NE(results().at(0).output.find("b.exr.nope"), std::string::npos);
}

TEST_F(Grader, TwoRendersCompareDirectlyThroughTheirVariances) {
  if (!test::haveReference()) GTEST_SKIP() << "needs the reference stages";
  const std::string render = std::string(PATHWAY_BINARY) + " render " + PATHWAY_SCENES_DIR +
                             "/cornell_box.gltf -q --width 48 --height 48 -i stage2@ref --spp 8";
  const std::string a = (dir_ / "a.exr").string(), b = (dir_ / "b.exr").string(),
                    c = (dir_ / "c.exr").string();
  ASSERT_EQ(test::runCommand(render + " --seed 1 -o " + a).exitCode, 0);
  ASSERT_EQ(test::runCommand(render + " --seed 2 -o " + b).exitCode, 0);
  ASSERT_EQ(test::runCommand(render + " --seed 3 -p ao-distance=0.5 -o " + c).exitCode, 0);
  EXPECT_EQ(grade("--image " + a + " --reference " + b).exitCode, 0) << results().at(0).output;
  EXPECT_EQ(grade("--image " + a + " --reference " + c).exitCode, 1);
  EXPECT_NE(results().at(0).output.find("other settings (params"), std::string::npos);
}

// The diagnosis must not point a render without NEE at NEE: whether it used it comes from the
// stage's NextEventEstimation option, as the render's metadata lists its parameters.
TEST(NextEventEstimationOfARender, ComesFromTheStagesDeclaredOption) {
  EXPECT_FALSE(usedNextEventEstimation(5, "max-depth=5 rr-depth=3 nee=off light-pick=area"));
  EXPECT_TRUE(usedNextEventEstimation(5, "max-depth=5 rr-depth=3 nee=on light-pick=area"));
  EXPECT_TRUE(usedNextEventEstimation(5, "max-depth=5"));  // not listed: its default, on
  EXPECT_FALSE(usedNextEventEstimation(4, "branching=3 depth=2 max-rays=1000000"));
  EXPECT_FALSE(usedNextEventEstimation(2, "ao-rays=4 ao-distance=0.25"));
  // Two files compared: no case says which stage, the render's metadata may not either.
  EXPECT_TRUE(usedNextEventEstimation(0, ""));
  EXPECT_TRUE(usedNextEventEstimation(5, "nee=maybe"));  // not a value: the default stands
}

TEST(CasePoints, AddUpToTheStageExactlyInWholeHundredths) {
  for (int count = 1; count <= 12; ++count) {
    long total = 0, smallest = 1 << 30, largest = 0;
    for (int i = 0; i < count; ++i) {
      const double points = casePoints(i, count);
      const long hundredths = std::lround(100.0 * points);
      EXPECT_NEAR(points, hundredths / 100.0, 1e-12) << "case " << i << " of " << count;
      total += hundredths;
      smallest = std::min(smallest, hundredths);
      largest = std::max(largest, hundredths);
    }
    EXPECT_EQ(total, std::lround(100.0 * kPointsPerStage)) << count << " cases";
    EXPECT_LE(largest - smallest, 1) << count << " cases";
  }
  // Summed as hundredths: three cases of 20/3 make 20.00, not 19.999...
  GradeSummary summary;
  for (int i = 0; i < 3; ++i) summary.cases.emplace_back().points = casePoints(i, 3);
  EXPECT_EQ(summary.points(), kPointsPerStage);
}

// ---- The mutant suite (tests/mutants/CMakeLists.txt) ----
#ifdef PATHWAY_MUTANT_LIST

using test::Mutant;
using test::mutants;

class GraderMutant : public Grader, public ::testing::WithParamInterface<Mutant> {};

TEST_P(GraderMutant, IsJudgedByItsImage) {
  const Mutant& mutant = GetParam();
  const std::string stage = " --stage " + std::to_string(mutant.stage);
  // A hang is stopped after 3 s; the other cases render in well under a second. (Where one case
  // hangs, the grader's own per-case limit, at least 15 s, stops it.)
  const std::string limit = mutant.expect == "hang" ? " --time-limit 3" : " --time-limit 60";
  const test::CommandOutcome outcome = grade("--stages-library " + mutant.library + stage + limit);
  const std::vector<ResultLine> lines = results();
  ASSERT_FALSE(lines.empty()) << outcome.output;
  size_t failed = 0, imageFailed = 0, crashed = 0, timedOut = 0;
  for (const ResultLine& line : lines) {
    // A likely cause exactly where an image was compared and failed: never on a passing case.
    const bool wrongImage = line.image == "fail" && line.status == "failed";
    EXPECT_EQ(!line.cause.empty(), wrongImage) << line.name << ": " << line.output;
    EXPECT_EQ(line.output.find("likely cause: ") != std::string::npos, wrongImage) << line.name;
    failed += line.status == "failed";
    imageFailed += line.image == "fail";
    crashed += line.output.find("crashed (signal") != std::string::npos;
    timedOut += line.output.find("ran past its time limit") != std::string::npos;
  }
  if (mutant.expect == "pass") {
    EXPECT_EQ(outcome.exitCode, 0) << mutant.description << "\n"
                                   << test::readTextFile((dir_ / "report/results.json").string());
    EXPECT_EQ(failed, 0u);
    size_t noted = 0;
    for (const ResultLine& line : lines)
      noted += line.output.find("times as noisy as the reference's") != std::string::npos;
    if (mutant.cause == "noisier") {
      EXPECT_GE(noted, 1u) << "no case notes the extra noise";
    }
  } else if (mutant.expect == "fail") {
    EXPECT_EQ(outcome.exitCode, 1) << mutant.description;
    EXPECT_GE(imageFailed, 1u) << mutant.description << ": no case of stage " << mutant.stage
                               << " saw the bug";
    EXPECT_EQ(crashed + timedOut, 0u);
    if (mutant.cause == "noise") {
      // A required technique left out: the case built to see it names it.
      size_t named = 0;
      for (const ResultLine& line : lines)
        named +=
            line.cause == "noise" && line.output.find("README.md, Required") != std::string::npos;
      EXPECT_GE(named, 1u) << test::readTextFile((dir_ / "report/results.json").string());
    }
  } else if (mutant.expect == "crash-one") {
    // One case crashes; the others (those before it in the same child, those after it in a new
    // child) are judged and pass.
    EXPECT_EQ(outcome.exitCode, 1);
    EXPECT_EQ(crashed, 1u) << test::readTextFile((dir_ / "report/results.json").string());
    EXPECT_EQ(failed, 1u);
    EXPECT_EQ(lines.size(), gradingCasesOf(2).size());
    // The message names the case, its settings and the pixel, and what the stage printed.
    for (const ResultLine& line : lines)
      if (line.status == "failed") {
        EXPECT_NE(line.output.find("in case stage2-ceiling (ceiling.gltf, 64x64, 8 spp)"),
                  std::string::npos)
            << line.output;
        EXPECT_NE(line.output.find("while rendering pixel"), std::string::npos) << line.output;
        EXPECT_NE(line.output.find("it printed nothing before it stopped"), std::string::npos)
            << line.output;
      }
  } else if (mutant.expect == "hang-one") {
    // One case runs past the limit and fails with that reason; every other case is judged and
    // passes.
    EXPECT_EQ(outcome.exitCode, 1);
    EXPECT_EQ(timedOut, 1u) << test::readTextFile((dir_ / "report/results.json").string());
    EXPECT_EQ(failed, 1u);
    EXPECT_EQ(crashed, 0u);
    EXPECT_EQ(lines.size(), gradingCasesOf(mutant.stage).size());
    for (const ResultLine& line : lines)
      if (line.status == "failed") {
        EXPECT_NE(line.output.find("in case stage5-furnace-unlimited-depth"), std::string::npos)
            << line.output;
        EXPECT_NE(line.output.find("while rendering pixel"), std::string::npos) << line.output;
      }
  } else {
    // Every case of the stage fails with the reason; the grader itself finishes.
    EXPECT_EQ(outcome.exitCode, 1);
    EXPECT_EQ(failed, lines.size());
    EXPECT_EQ(mutant.expect == "crash" ? crashed : timedOut, lines.size())
        << test::readTextFile((dir_ / "report/results.json").string());
    for (const ResultLine& line : lines)
      EXPECT_NE(line.output.find("while rendering pixel"), std::string::npos) << line.output;
  }
}

INSTANTIATE_TEST_SUITE_P(Mutants, GraderMutant, ::testing::ValuesIn(mutants()),
                         [](const ::testing::TestParamInfo<Mutant>& info) {
                           return info.param.name;
                         });

#endif  // PATHWAY_MUTANT_LIST

}  // namespace
}  // namespace pathway
