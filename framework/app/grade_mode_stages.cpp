// `pathway grade [--stage N]... [--together]`: the stages on their grading cases, each on the
// reference's earlier stages (or, --together, on the student's own), into --report.
#include "app/grade_modes.h"
#include "render/integrator_registry.h"
#include "render/reference_library.h"

namespace pathway {

int gradeStagesMode(const GradeOptions& options) {
  const ComparisonSettings settings;
  GradingRun run = gradingRun(options);
  // Without reference stages (a handout whose library is missing or refused) there are none to
  // put under yours: grade yours together, and say why.
  const bool noReference = !findStageIntegrator(1, Variant::Reference);
  if (noReference) run.together = true;
  GradeSummary summary = gradeStages(run, settings);
  if (noReference && !options.together)
    summary.notes.push_back("There are no reference stages here (" + referenceStagesProblem() +
                            "), so your stages are graded together: a bug in an earlier stage "
                            "also fails the stages after it.");
  const std::string notHere = courseCasesNotHere(options.references);
  if (!notHere.empty()) summary.notes.push_back(notHere);
  return writeGradeSummary(summary, options, settings);
}

}  // namespace pathway
