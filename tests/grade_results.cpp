#include "grade_results.h"

namespace pathway::test {

std::vector<CaseLine> caseLines(const std::string& json) {
  std::vector<CaseLine> lines;
  for (size_t at = json.find("{\"name\""); at != std::string::npos;
       at = json.find("{\"name\"", at + 1)) {
    const size_t end = json.find('\n', at);
    const std::string line = json.substr(at, end - at);
    auto field = [&](const std::string& key) {
      const size_t start = line.find("\"" + key + "\": \"");
      if (start == std::string::npos) return std::string();
      const size_t from = start + key.size() + 5;
      return line.substr(from, line.find('"', from) - from);
    };
    const size_t output = line.find("\"output\": \"");
    lines.push_back({field("name"), field("status"), field("image"), field("likely_cause"),
                     output == std::string::npos ? "" : line.substr(output)});
  }
  return lines;
}

std::map<std::string, std::string> caseStatuses(const std::string& json) {
  std::map<std::string, std::string> statuses;
  for (const CaseLine& line : caseLines(json)) statuses[line.name] = line.status;
  return statuses;
}

}  // namespace pathway::test
