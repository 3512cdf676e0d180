// Two image files compared (`pathway grade --image A --reference B`): a render against a grading
// reference (a file with its replicates' tile variance), or against another render (each with its
// own per-pixel variance). The verdict comes as a one-case GradeSummary, so it is reported like a
// stage's.
#pragma once

#include <string>

#include "grade/grade_report.h"

namespace pathway {

// Never throws for the files: a file that cannot be read, or that does not match, is the case's
// problem (and a failure).
GradeSummary compareImageFiles(const std::string& image, const std::string& reference,
                               const ComparisonSettings& settings);

}  // namespace pathway
