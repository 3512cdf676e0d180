// How `pathway grade` and `pathway grade --image` end: the verdicts written and printed.
#include <cstdio>
#include <map>

#include "app/grade_modes.h"

namespace pathway {

int writeGradeSummary(const GradeSummary& summary, const GradeOptions& options,
                      const ComparisonSettings& settings) {
  // results.json goes first, or into the report folder as it moves into place.
  const std::string results =
      options.results.empty() ? options.report + "/results.json" : options.results;
  if (!options.results.empty()) writeGradescopeResults(results, summary, settings);
  std::map<std::string, std::string> extra;
  if (options.results.empty()) extra["results.json"] = gradescopeResults(summary, settings);
  writeHtmlReport(options.report, summary, settings, extra);
  if (!options.quiet) {
    for (const std::string& note : summary.notes) std::printf("%s\n", note.c_str());
    for (const CaseResult& c : summary.cases)
      std::printf("%-40s %s\n", c.title.c_str(), c.passed ? "passed" : "FAILED");
    for (const CaseResult& c : summary.checks)
      std::printf("%-40s %s\n", c.title.c_str(), c.passed ? "passed" : "FAILED");
    std::printf("%.1f / %.1f points; report %s/index.html, results %s\n", summary.points(),
                summary.maxPoints(), options.report.c_str(), results.c_str());
  }
  return summary.passed() ? 0 : 1;
}

}  // namespace pathway
