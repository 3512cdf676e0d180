#include "app/grade_options.h"

#include <set>

#include "stages/stage_catalog.h"

namespace pathway {

std::vector<const GradingCase*> selectedCases(const GradeOptions& options) {
  std::vector<const GradingCase*> selected;
  for (const std::string& id : options.cases) selected.push_back(&findGradingCase(id));
  if (!selected.empty()) return selected;
  std::set<int> stages(options.stages.begin(), options.stages.end());
  if (stages.empty())
    for (int stage = 1; stage <= kStageCount; ++stage) stages.insert(stage);
  for (int stage : stages)
    for (const GradingCase* c : gradingCasesOf(stage)) selected.push_back(c);
  return selected;
}

GradingRun gradingRun(const GradeOptions& options) {
  GradingRun run;
  run.cases = selectedCases(options);
  run.together = options.together;
  run.gradeReference = options.gradeReference;
  run.tracing = options.referenceTracing();
  run.stageLibraries = options.stageLibraries;
  run.references = options.references;
  run.scenes = kScenesDir;
  run.timeLimit = options.timeLimit;
  run.seed = options.seed;
  run.progress = !options.quiet;
  run.sandbox = options.sandbox;
  return run;
}

}  // namespace pathway
