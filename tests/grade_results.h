// Reads back the cases of a results.json that `pathway grade` wrote (Gradescope's format), by
// plain text search: enough for a file this program wrote itself in a fixed layout.
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
  std::string output;  // from "output" to the end of the line
};

std::vector<CaseLine> caseLines(const std::string& json);
// Each case's status by its name.
std::map<std::string, std::string> caseStatuses(const std::string& json);

}  // namespace pathway::test
