// A class graded on one machine: every submission in a folder is built on its own (a stage
// library in its own build folder) and graded like one student's; a submission that does not
// build, crashes, hangs or lacks files gets that in its results and never stops the others.
// Writes <output>/<submission>/report/ and results.json, and the class table
// <output>/index.html and <output>/class.csv.
#pragma once

#include <string>
#include <vector>

#include "grade/stage_grading.h"

namespace pathway {

struct ClassGrading {
  std::string submissions;  // a folder of submission folders
  std::string output;
  GradingRun run;  // cases, references, time limit; the stage library is set per submission
  double buildTimeLimit = 300.0;
};

struct SubmissionResult {
  std::string name;
  double points = 0.0, maxPoints = 0.0;
  std::vector<double> stagePoints;  // index 0 is stage 1
  double buildSeconds = 0.0, gradeSeconds = 0.0;
  std::string status;  // "graded", "graded; stage 2 did not compile; stage 4 crashed", ...
  std::string causes;  // likely causes of the failing cases: "stage 2: scale; stage 5: lit, local"
};

std::vector<SubmissionResult> gradeClass(const ClassGrading& grading,
                                         const ComparisonSettings& settings);

// The class table from results already in `grading.output` (graded one submission at a time,
// e.g. by the tasks of a cluster job): a submission without results gets a row that says so.
std::vector<SubmissionResult> classTableFromResults(const ClassGrading& grading);
// The same rows, read only.
std::vector<SubmissionResult> readClassResults(const ClassGrading& grading);

// The submission folders in `submissions`, sorted; throws PathwayError when there are none.
std::vector<std::string> submissionFolders(const std::string& submissions);

// The stage files in `folder` (a submission, or a handout's assignments/), each built on its own
// in `buildFolder` and graded on `run`'s cases; only the stages with cases are built. A stage
// whose file does not compile or is missing fails its own cases with the reason (the compiler's
// message is one of the summary's notes); the others are graded.
struct StageFilesGrade {
  GradeSummary summary;
  double buildSeconds = 0.0;
  std::string status;  // "graded", "graded; stage 2 did not compile; stage 4 crashed", ...
};
StageFilesGrade gradeStageFiles(const std::string& folder, const std::string& buildFolder,
                                const GradingRun& run, double buildTimeLimit,
                                const ComparisonSettings& settings);

// One submission: builds `folder` in `output`/build and writes `output`/report/,
// `output`/results.json (Gradescope's autograder runs this for each student) and its row of the
// class table, `output`/submission.tsv.
SubmissionResult gradeSubmission(const std::string& folder, const std::string& output,
                                 const GradingRun& run, double buildTimeLimit,
                                 const ComparisonSettings& settings);

}  // namespace pathway
