// The options `pathway render` and `pathway view` share, declared once so that their names,
// help texts and ranges cannot drift apart.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <string>
#include <vector>

namespace pathway {

struct SharedOptions {  // where the parsed values go
  std::string& scene;
  std::string& integrator;
  std::vector<std::string>& params;  // name=value
  std::string& sampler;              // empty: the integrator's own default
  uint64_t& seed;
  std::string& filter;
  float& filterRadius;  // 0: the filter's natural radius
};

void addSharedOptions(CLI::App& command, const SharedOptions& options);

}  // namespace pathway
