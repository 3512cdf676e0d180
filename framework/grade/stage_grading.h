// Grading stages on their cases: a stage's cases render in a child process of this program (a
// CaseRenderJob, grade/case_render_job.h), one after another, each with its own time limit, so
// that a stage that crashes or hangs fails that case and nothing else (the cases after it render
// in a new child); this process reads the renders back and compares them with the references.
#pragma once

#include <string>
#include <vector>

#include "core/sandbox.h"
#include "grade/grade_report.h"
#include "grade/grading_cases.h"
#include "grade/grading_reference.h"
#include "io/image_io.h"

namespace pathway {

constexpr double kPointsPerStage = 20.0;  // split evenly over the stage's cases
// A case may render for kCaseTimeFactor times the reference's time, at least
// kMinimumCaseSeconds, at most GradingRun::timeLimit.
constexpr double kCaseTimeFactor = 50.0;
constexpr double kMinimumCaseSeconds = 15.0;
// A failed case is rendered again with this much added to the seed; it fails only if both fail.
constexpr uint64_t kConfirmationSeedOffset = 1000;

struct GradingRun {
  std::vector<const GradingCase*> cases;
  bool together = false;        // the student's earlier stages instead of the reference's
  bool gradeReference = false;  // grade the reference stages themselves (calibration, tests)
  // How references render: their wavefront versions where they exist, or one ray at a time.
  ReferenceTracing tracing = ReferenceTracing::Fastest;
  // Student stages built on their own (stage_loading/stage_library.h), loaded over the built-in
  // ones.
  std::vector<std::string> stageLibraries;
  std::string references;    // folder of the reference files
  std::string scenes;        // folder of the scenes
  double timeLimit = 120.0;  // seconds per case
  uint64_t seed = kStudentSeed;
  bool progress = true;  // one line per case on stderr
  // How the children shut themselves in before they load a stage (core/sandbox.h).
  SandboxMode sandbox = SandboxMode::Auto;
  // After the cases of stages 2 and 5, their sampling routine's warp test, in a child of its own
  // (grade/stage_warp_test.h): a check beside the cases, with no points (GradeSummary::checks).
  bool warpTests = true;
};

// The points of case `index` of a stage's `count` cases: kPointsPerStage split into whole
// hundredths that differ by at most one and add up to it exactly (20/3: 6.67, 6.67, 6.66).
double casePoints(int index, int count);

// Grades every case of the run; never throws for a case (its problem is in its result). Throws
// PathwayError before grading anything when run.sandbox is Require and this machine cannot shut
// student code in.
GradeSummary gradeStages(const GradingRun& run, const ComparisonSettings& settings);

// Whether a render of `stage` with these parameters ("name=value ...", as its metadata has
// them) sampled the emitters: the value of the option the stage declares with that role
// (render/parameters.h), so the grader names no parameter; a stage without one never does, and a
// render of no course stage (0) may have.
bool usedNextEventEstimation(int stage, const std::string& renderedParams);

// Fills in `result` from a render and its reference: verdict, images, timings, TODOs that ran.
void judgeAgainstReference(CaseResult& result, const LoadedImage& render,
                           const GradingReference& reference, const ComparisonSettings& settings);

}  // namespace pathway
