// What `pathway grade` was asked: its options (declared in grade_command.cpp), and what the modes
// make of them: the grading cases chosen and the GradingRun that grades them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grade/grading_cases.h"
#include "grade/stage_grading.h"

namespace pathway {

// The course's scenes, and under them the shipped references.
inline const std::string kScenesDir = PATHWAY_SOURCE_DIR "/scenes";

struct GradeOptions {
  std::vector<int> stages;  // empty: all
  std::vector<std::string> cases;
  bool together = false;
  bool gradeReference = false;
  bool singleRay = false;  // references one ray at a time (stageN@ref), not stageN@fast
  std::vector<std::string> stageLibraries;
  std::string references = kScenesDir + "/references";
  std::string report = "grade-report";
  std::string results;  // empty: <report>/results.json
  double timeLimit = 120.0;
  uint64_t seed = kStudentSeed;
  std::string image, reference;
  std::string submissions;  // a folder of submission folders
  std::string submission;   // one submission folder
  std::string output = "grade-output";
  bool tableOnly = false;  // with --submissions: the class table from results in --output
  bool makeReferences = false;
  bool listCases = false;
  int calibrate = 0;                     // > 0: grade this many seeds per case, in this process
  std::vector<uint32_t> calibrationSpp;  // empty: each case's own
  bool verdictSeeds = false;             // with calibrate: list every seed that got a verdict
  bool quiet = false;
  // How student code is shut in while it compiles and renders (core/sandbox.h).
  SandboxMode sandbox = SandboxMode::Auto;

  ReferenceTracing referenceTracing() const {
    return singleRay ? ReferenceTracing::SingleRay : ReferenceTracing::Fastest;
  }
};

// The cases named with --case; else those of the --stage options; else every case.
std::vector<const GradingCase*> selectedCases(const GradeOptions& options);
// The selected cases, graded as the options say.
GradingRun gradingRun(const GradeOptions& options);

}  // namespace pathway
