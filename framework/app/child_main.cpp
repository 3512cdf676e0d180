// pathway-child: the program the grader runs student code in (grade/case_render_job.h). It is the
// framework, the course's grading cases and the stage API, and no reference stage: a job loads the
// reference stages it may hold (for a student's stage N, those below N) from their sealed
// libraries, shuts itself in, and only then loads the student's library. So the process that runs
// a student's stage N holds nothing of the reference's stage N or any later one, whatever that
// stage does in it. It also seals the reference libraries the build makes (the seal is this
// framework's stage interface and platform, stage_loading/reference_library.h).
//   pathway-child render-grading-cases ...   the grader's job (its command line, from the grader)
//   pathway-child seal LIBRARY                seal a freshly linked reference library
#include <cstdio>
#include <string>
#include <vector>

#include "app/reporting_errors.h"
#include "grade/case_render_job.h"
#include "render/registration_gate.h"
#include "stage_loading/reference_library.h"

int main(int argc, char** argv) {
  // Nothing registers from here on but the libraries a job loads, each in its own window.
  pathway::endBuiltInRegistrations();
  const std::vector<std::string> arguments(argv + 1, argv + argc);
  return pathway::runReportingErrors([&] {
    if (!arguments.empty() && arguments[0] == pathway::CaseRenderJob::kCommand) {
      pathway::runCaseRenderJob(pathway::CaseRenderJob::fromArguments(arguments));
      return 0;
    }
    if (arguments.size() == 2 && arguments[0] == "seal") {
      pathway::sealReferenceLibrary(arguments[1]);
      return 0;
    }
    std::fprintf(stderr,
                 "pathway-child: the grader's own program (usage: pathway-child %s ... | seal "
                 "LIBRARY); grade with `pathway grade`\n",
                 pathway::CaseRenderJob::kCommand);
    return 2;
  });
}
