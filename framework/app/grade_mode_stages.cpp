// `pathway grade [--stage N]... [--together]`: the stages on their grading cases, each on the
// reference's earlier stages (or, --together, on the student's own), into --report. The student's
// stage files are built here as the autograder builds a submission: each on its own, the compiler
// and the renders sandboxed, so that a stage that does not compile fails only its own cases.
#include <filesystem>

#include "app/grade_modes.h"
#include "core/temporary_folder.h"
#include "grade/class_grading.h"
#include "stage_loading/reference_library.h"

namespace pathway {
namespace {

const std::string kStudentStagesFolder = PATHWAY_SOURCE_DIR "/assignments";

}  // namespace

int gradeStagesMode(const GradeOptions& options) {
  const ComparisonSettings settings;
  GradingRun run = gradingRun(options);
  // Without the reference stages' libraries (a handout whose libraries are missing or refused),
  // the grader's child has none to put under yours: grade yours together, and say why.
  const std::string referenceProblem = referenceLibrariesProblem();
  const bool noReference = !referenceProblem.empty();
  if (noReference) run.together = true;
  GradeSummary summary;
  if (run.gradeReference || !run.stageLibraries.empty()) {
    summary = gradeStages(run, settings);  // the reference, or stage libraries built elsewhere
  } else {
    const TemporaryFolder build("pathway-self-grade");
    // Open to the sandbox's user (nobody, under root), which reads the libraries built in it.
    namespace fs = std::filesystem;
    fs::permissions(build.path(), fs::perms::owner_all | fs::perms::group_read |
                                      fs::perms::group_exec | fs::perms::others_read |
                                      fs::perms::others_exec);
    summary = gradeStageFiles(kStudentStagesFolder, build.path() + "/build", run,
                              ClassGrading().buildTimeLimit, settings)
                  .summary;
    if (summary.title.empty()) summary.title = "Pathway grading: your stages";  // none compiled
  }
  if (noReference && !options.together)
    summary.notes.push_back("There are no reference stages here (" + referenceProblem +
                            "), so your stages are graded together: a bug in an earlier stage "
                            "also fails the stages after it.");
  const std::string notHere = courseCasesNotHere(options.references);
  if (!notHere.empty()) summary.notes.push_back(notHere);
  return writeGradeSummary(summary, options, settings);
}

}  // namespace pathway
