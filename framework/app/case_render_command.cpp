// `pathway render-grading-cases ...`: the grader's child (grade/case_render_job.h), hidden from
// --help. Only the grader runs it, with the command line CaseRenderJob::toArguments() wrote;
// CLI11 sees the subcommand's name only, and the job's own parser reads the rest.
#include "app/commands.h"
#include "grade/case_render_job.h"

namespace pathway {

std::vector<std::string>& unparsedArguments() {
  static std::vector<std::string> arguments;
  return arguments;
}

Command addCaseRenderCommand(CLI::App& app) {
  CLI::App* child = app.add_subcommand(CaseRenderJob::kCommand, "The grader's child process");
  child->group("");  // not listed
  return {child, [] {
            runCaseRenderJob(CaseRenderJob::fromArguments(unparsedArguments()));
            return 0;
          }};
}

}  // namespace pathway
