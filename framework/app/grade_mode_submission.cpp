// `pathway grade --submission DIR --output OUT`: one submission built and graded, what
// Gradescope's autograder runs for each student.
#include <cstdio>

#include "app/grade_modes.h"
#include "grade/class_grading.h"

namespace pathway {

int gradeSubmissionMode(const GradeOptions& options) {
  const SubmissionResult result =
      gradeSubmission(options.submission, options.output, gradingRun(options),
                      ClassGrading().buildTimeLimit, ComparisonSettings());
  if (!options.quiet)
    std::printf("%s: %.1f / %.1f points, %s; %s/report/index.html, %s/results.json\n",
                result.name.c_str(), result.points, result.maxPoints, result.status.c_str(),
                options.output.c_str(), options.output.c_str());
  return result.points == result.maxPoints ? 0 : 1;
}

}  // namespace pathway
