// Reads back a results.json that `pathway grade` wrote (Gradescope's format) with a JSON parser,
// so a file that is not valid JSON fails the test that reads it.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pathway::test {

struct CaseLine {
  std::string name;    // "Stage 2 · ceiling"
  std::string status;  // "passed" or "failed"
  std::string image;   // extra_data.image: "pass", "fail" or "none"
  std::string cause;   // extra_data.likely_cause: "" or "scale", "edges", ...
  std::string output;  // what the case says: its verdict, figures, likely cause
  double score = 0.0;  // its points
  double noiseRatio =
      0.0;  // extra_data.noise_ratio: times as noisy as the reference (0: not measured)
};

// The cases' lines (the checks beside them left out).
std::vector<CaseLine> caseLines(const std::string& json);
// The overall score.
double score(const std::string& json);
// Each case's status by its name (the checks beside the cases left out).
std::map<std::string, std::string> caseStatuses(const std::string& json);
// Each check's status by its name: the warp tests beside the cases, which carry no points (a
// check with a max_score other than 0 fails the test that reads it).
std::map<std::string, std::string> checkStatuses(const std::string& json);

}  // namespace pathway::test
