// `pathway grade --submissions DIR [--table-only]`: every submission folder in DIR built and
// graded one after another, then the class table; or, --table-only, the table alone from the
// results already in --output (pathway cluster grade's last step).
#include <cstdio>

#include "app/grade_modes.h"
#include "grade/class_grading.h"

namespace pathway {

int gradeClassMode(const GradeOptions& options) {
  ClassGrading grading;
  grading.submissions = options.submissions;
  grading.output = options.output;
  grading.run = gradingRun(options);
  const std::vector<SubmissionResult> rows = options.tableOnly
                                                 ? classTableFromResults(grading)
                                                 : gradeClass(grading, ComparisonSettings());
  if (!options.quiet) {
    for (const SubmissionResult& r : rows)
      std::printf("%-24s %5.1f / %5.1f  %s\n", r.name.c_str(), r.points, r.maxPoints,
                  r.status.c_str());
    std::printf("class table: %s/index.html and %s/class.csv\n", grading.output.c_str(),
                grading.output.c_str());
  }
  return 0;
}

}  // namespace pathway
