// The framework's folders are layers: a file includes only its own folder and the folders below
// it, so each layer can be read (and built) without those above. docs/design.md lists them in
// this order.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Lowest first. A new folder must be placed here.
const std::vector<std::string> kLayers = {
    "core",   "sampling",      "scene", "film",    "io",    "render", "stages",
    "engine", "stage_loading", "grade", "cluster", "chart", "viewer", "app"};

struct Include {
  std::string file;    // "render/stage_kit.cpp"
  std::string folder;  // the folder of the header it includes: "engine"
};

// Every include of another framework folder's header in the files under `framework`.
std::vector<Include> frameworkIncludes(const fs::path& framework) {
  const std::regex include(R"re(^\s*#\s*include\s*"([a-z_]+)/[^"]+")re");
  std::vector<Include> found;
  for (const auto& entry : fs::recursive_directory_iterator(framework)) {
    const std::string extension = entry.path().extension().string();
    if (!entry.is_regular_file() || (extension != ".h" && extension != ".cpp")) continue;
    const std::string file = fs::relative(entry.path(), framework).generic_string();
    std::ifstream in(entry.path());
    std::smatch match;
    for (std::string line; std::getline(in, line);)
      if (std::regex_search(line, match, include)) found.push_back({file, match[1]});
  }
  return found;
}

int rankOf(const std::string& folder) {
  const auto it = std::find(kLayers.begin(), kLayers.end(), folder);
  return it == kLayers.end() ? -1 : static_cast<int>(it - kLayers.begin());
}

// One line per include that goes up, or to a folder that has no layer.
std::vector<std::string> layerViolations(const std::vector<Include>& includes) {
  std::vector<std::string> problems;
  for (const Include& include : includes) {
    const std::string from = include.file.substr(0, include.file.find('/'));
    const int fromRank = rankOf(from), toRank = rankOf(include.folder);
    if (fromRank < 0 || toRank < 0)
      problems.push_back(include.file + " includes from " + include.folder + "/: " +
                         (fromRank < 0 ? from : include.folder) + " has no layer in kLayers");
    else if (toRank > fromRank)
      problems.push_back(include.file + " includes " + include.folder + "/, a layer above " + from +
                         "/");
  }
  return problems;
}

TEST(Layers, FindsAnIncludeThatGoesUp) {
  const std::vector<std::string> problems =
      layerViolations({{"render/stage_kit.cpp", "render"},
                       {"render/stage_kit.cpp", "core"},
                       {"render/stage_kit.cpp", "stage_loading"},
                       {"plugins/x.cpp", "core"}});
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "render/stage_kit.cpp includes stage_loading/, a layer above render/");
  EXPECT_NE(problems[1].find("plugins has no layer"), std::string::npos) << problems[1];
}

TEST(Layers, FrameworkIncludesOnlyDownward) {
  const std::vector<Include> includes = frameworkIncludes(PATHWAY_FRAMEWORK_DIR);
  ASSERT_GT(includes.size(), 300u) << "the framework's includes were not found";
  std::string report;
  for (const std::string& problem : layerViolations(includes)) report += problem + "\n";
  EXPECT_TRUE(report.empty()) << report;
}

}  // namespace
