// The modes of `pathway grade`, one file each (grade_mode_*.cpp); grade_command.cpp declares the
// options and picks the mode they ask for. Each mode returns the exit status and throws
// PathwayError on bad input.
#pragma once

#include "app/grade_options.h"
#include "grade/grade_report.h"

namespace pathway {

int gradeStagesMode(const GradeOptions& options);      // the default: the stages, into --report
int compareFilesMode(const GradeOptions& options);     // --image with --reference
int gradeClassMode(const GradeOptions& options);       // --submissions [--table-only]
int gradeSubmissionMode(const GradeOptions& options);  // --submission
int makeReferencesMode(const GradeOptions& options);   // --make-references
int calibrateMode(const GradeOptions& options);        // --calibrate
int listCasesMode(const GradeOptions& options);        // --list-cases

// What the modes that grade into --report end with (grade_mode_summary.cpp): results.json (at
// --results, or in the report), the HTML report, and unless --quiet a line per case and the
// total. Returns 0 when every case passed, else 1.
int writeGradeSummary(const GradeSummary& summary, const GradeOptions& options,
                      const ComparisonSettings& settings);

}  // namespace pathway
