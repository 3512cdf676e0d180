// The grader's child process as one type. The grader (stage_grading.cpp) renders a stage's cases
// in a child process, so that a stage that crashes or hangs fails its own case and nothing else.
// The child is its own program, pathway-child (app/child_main.cpp): the framework without any
// reference stage built in. It loads the reference stages the job names (for a student's stage N
// the reference's stages below N at most, stage_loading/reference_library.h), shuts itself in,
// and only then loads the student's library: the process that runs student code holds nothing of
// the reference of the stage it grades. What a child renders is a CaseRenderJob: grading cases of
// one stage, each within its time limit, into a folder, with a seed and a choice of stages. The
// job travels as the child's command line, `pathway-child render-grading-cases ...`, written by
// toArguments() in the parent and read back by fromArguments() in the child. Both directions, and
// the child's work, are in case_render_job.cpp and nowhere else, so the two ends cannot disagree
// about a flag.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/sandbox.h"
#include "grade/grading_cases.h"

namespace pathway {

struct CaseRenderJob {
  // The command of `pathway-child` that runs a job: the first word of toArguments().
  static constexpr const char* kCommand = "render-grading-cases";

  struct Case {
    const GradingCase* gradingCase = nullptr;
    double timeLimit = 0.0;  // seconds; past it, SIGALRM ends the child
  };
  std::vector<Case> cases;  // rendered in this order
  std::string output;       // the folder the renders go to (imagePath)
  std::string scenes;       // the folder of the scenes
  uint64_t seed = kStudentSeed;
  bool together = false;        // the student's earlier stages instead of the reference's
  bool gradeReference = false;  // the reference stages themselves instead of the student's
  bool singleRay = false;       // with gradeReference: stageN@ref even where stageN@fast exists
  // Stage libraries (stage_loading/stage_library.h) loaded before rendering, in this order. The
  // parent gives absolute paths: the child may resolve a relative one differently.
  std::vector<std::string> stageLibraries;
  // The reference stages the child loads (sealed libraries in `referenceFolder`), before it shuts
  // itself in: referenceStagesFor() says which.
  std::vector<int> referenceStages;
  std::string referenceFolder;
  // The child writes what its sandbox holds to kChildReportDescriptor (core/child_process.h)
  // before it loads any student code, and closes it.
  bool reportsSandbox = false;
  // How the child shuts itself in before it loads them (core/sandbox.h).
  SandboxMode sandbox = SandboxMode::Auto;
  // After the cases (a job may have none then): the warp test of this stage's sampling routine
  // (grade/stage_warp_test.h), within kWarpTestSeconds, its outcome written to warpTestPath().
  // 0: none.
  int warpTestStage = 0;
  static constexpr double kWarpTestSeconds = 10.0;

  // The reference stages a job of `stage` may hold: stages 1..stage when it grades the reference
  // itself, 1..stage-1 for a student's stage on the reference's earlier stages, none together.
  static std::vector<int> referenceStagesFor(int stage, bool gradeReference, bool together);

  // What the child may touch once it is shut in: read its libraries, write in `output`; within
  // limits on memory, CPU time (the cases' limits on every core), open files and file size.
  SandboxPolicy sandboxPolicy() const;

  // The child's command line after the program's path: kCommand, then the job.
  std::vector<std::string> toArguments() const;
  // The job from a command line toArguments() wrote (kCommand first). Throws one PathwayError that
  // names the first argument it cannot take: unknown, repeated, without its value or malformed
  // (a time limit or seed that is not a number, an unknown case), or one that is missing.
  static CaseRenderJob fromArguments(const std::vector<std::string>& arguments);

  // Where the child writes the render of `gradingCase`: a file in `output` named after the case
  // and the seed. It is there only once the case is finished (images are written whole).
  std::string imagePath(const GradingCase& gradingCase) const;
  // Where the child writes the warp test's outcome: "passed" or "failed" on the first line, the
  // verdict after it. Written whole, once the test is done.
  std::string warpTestPath() const;
};

bool operator==(const CaseRenderJob::Case& a, const CaseRenderJob::Case& b);
bool operator==(const CaseRenderJob& a, const CaseRenderJob& b);

// The child's part: reads the cases' scenes, loads the job's reference stages, shuts itself in
// (job.sandboxPolicy(), job.sandbox) and says so on its first line of output (and on its report
// descriptor), loads the stage libraries, and renders the job's cases
// in order, each into job.imagePath(case) and each within its own time limit (past it, SIGALRM
// ends the process: the parent then knows which case hung from the images that exist). Reports
// the pixels in progress when a signal ends it (engine/pixel_in_progress.h). Throws PathwayError
// when a stage a case needs is in none of the job's libraries.
void runCaseRenderJob(const CaseRenderJob& job);

}  // namespace pathway
