// `pathway grade [--stage N]... [--together]`: the stages on their grading cases, each on the
// reference's earlier stages (or, --together, on the student's own), into --report. The student's
// stage files are built here as the autograder builds a submission: each on its own, the compiler
// and the renders sandboxed, so that a stage that does not compile fails only its own cases.
#include <unistd.h>

#include <filesystem>

#include "app/grade_modes.h"
#include "grade/class_grading.h"
#include "render/integrator_registry.h"
#include "render/reference_library.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kStudentStagesFolder = PATHWAY_SOURCE_DIR "/assignments";

// A build folder of this run's own, removed when the grade is done.
struct ScratchFolder {
  fs::path path = fs::temp_directory_path() / ("pathway-self-grade-" + std::to_string(::getpid()));
  ScratchFolder() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

}  // namespace

int gradeStagesMode(const GradeOptions& options) {
  const ComparisonSettings settings;
  GradingRun run = gradingRun(options);
  // Without reference stages (a handout whose library is missing or refused) there are none to
  // put under yours: grade yours together, and say why.
  const bool noReference = !findStageIntegrator(1, Variant::Reference);
  if (noReference) run.together = true;
  GradeSummary summary;
  if (run.gradeReference || !run.stageLibraries.empty()) {
    summary = gradeStages(run, settings);  // the reference, or stage libraries built elsewhere
  } else {
    const ScratchFolder build;
    summary = gradeStageFiles(kStudentStagesFolder, (build.path / "build").string(), run,
                              ClassGrading().buildTimeLimit, settings)
                  .summary;
    if (summary.title.empty()) summary.title = "Pathway grading: your stages";  // none compiled
  }
  if (noReference && !options.together)
    summary.notes.push_back("There are no reference stages here (" + referenceStagesProblem() +
                            "), so your stages are graded together: a bug in an earlier stage "
                            "also fails the stages after it.");
  const std::string notHere = courseCasesNotHere(options.references);
  if (!notHere.empty()) summary.notes.push_back(notHere);
  return writeGradeSummary(summary, options, settings);
}

}  // namespace pathway
