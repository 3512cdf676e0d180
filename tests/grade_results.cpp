#include "grade_results.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace pathway::test {

std::vector<CaseLine> caseLines(const std::string& json) {
  // Throws nlohmann::json::parse_error on a file that is not JSON: the test then fails, naming it.
  const nlohmann::json results = nlohmann::json::parse(json);
  std::vector<CaseLine> lines;
  for (const nlohmann::json& test : results.at("tests")) {
    const nlohmann::json& extra = test.at("extra_data");
    if (extra.contains("check")) continue;  // a warp test beside the cases (checkStatuses)
    lines.push_back({test.at("name"), test.at("status"), extra.at("image"),
                     extra.at("likely_cause"), test.at("output"), test.at("score"),
                     extra.at("noise_ratio")});
  }
  return lines;
}

std::map<std::string, std::string> checkStatuses(const std::string& json) {
  std::map<std::string, std::string> statuses;
  const nlohmann::json results = nlohmann::json::parse(json);
  for (const nlohmann::json& test : results.at("tests"))
    if (test.at("extra_data").contains("check")) {
      EXPECT_EQ(test.at("max_score").get<double>(), 0.0) << test.at("name");
      statuses[test.at("name")] = test.at("status");
    }
  return statuses;
}

double score(const std::string& json) {
  return nlohmann::json::parse(json).at("score").get<double>();
}

std::map<std::string, std::string> caseStatuses(const std::string& json) {
  std::map<std::string, std::string> statuses;
  for (const CaseLine& line : caseLines(json)) statuses[line.name] = line.status;
  return statuses;
}

}  // namespace pathway::test
