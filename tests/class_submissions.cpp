#include "class_submissions.h"

#include <gtest/gtest.h>

#include <map>

#include "run_command.h"

namespace pathway::test {

namespace fs = std::filesystem;

bool makeTestClass(const fs::path& submissions) {
  // Each submission starts as the solutions (as a student's finished files), then is changed.
  const std::map<std::string, std::string> changes = {
      {"alice", "true"},
      {"bob", "sed -i 's/visibility \\* local.z/visibility/' stage2_nested_ao.cpp"},
      {"carol", "echo 'not C++' >> stage2_nested_ao.cpp"},
      {"dave",
       "sed -i 's/if (pdf <= 0.0f) return 0.0f;/if (pdf > -1.0f) __builtin_trap();/' "
       "stage2_nested_ao.cpp"},
      {"erin",
       "sed -i 's/if (pdf <= 0.0f) return 0.0f;/while (static_cast<const volatile "
       "float\\&>(pdf) > -1.0f) {}/' stage2_nested_ao.cpp"},
      {"frank", "rm stage2_nested_ao.cpp && echo notes > README.txt"},
  };
  for (const auto& [name, change] : changes) {
    const fs::path folder = submissions / name;
    fs::create_directories(folder);
    const CommandOutcome made =
        runCommand("cp " PATHWAY_SOURCE_DIR "/solutions/*/*.cpp " + folder.string() + " && cd " +
                   folder.string() + " && " + change);
    if (made.exitCode != 0) {
      ADD_FAILURE() << name << ": " << made.output;
      return false;
    }
  }
  return true;
}

std::string classRow(const std::string& table, const std::string& name) {
  const size_t at = table.find("\n\"" + name + "\",");
  return at == std::string::npos ? "" : table.substr(at + 1, table.find('\n', at + 1) - at - 1);
}

void expectTestClassVerdicts(const fs::path& output) {
  const std::string table = readTextFile((output / "class.csv").string());
  EXPECT_NE(classRow(table, "alice").find("\"alice\",20.0,20.0"), std::string::npos) << table;
  // A submission that passes has no likely cause; one with a wrong image has one for its stage.
  EXPECT_NE(classRow(table, "alice").find(",\"graded\",\"\""), std::string::npos) << table;
  EXPECT_NE(classRow(table, "bob").find(",\"graded\",\"stage 2: "), std::string::npos) << table;
  EXPECT_NE(classRow(table, "bob").find("\"bob\",0.0,20.0"), std::string::npos) << table;
  EXPECT_NE(classRow(table, "carol").find("\"carol\",0.0,20.0"), std::string::npos) << table;
  EXPECT_NE(classRow(table, "carol").find("stage 2 did not compile"), std::string::npos) << table;
  EXPECT_NE(classRow(table, "dave").find("stage 2 crashed"), std::string::npos) << table;
  EXPECT_NE(classRow(table, "erin").find("stage 2 ran past the time limit"), std::string::npos)
      << table;
  EXPECT_NE(classRow(table, "frank").find("stage 2 is missing"), std::string::npos) << table;
  for (const std::string name : {"alice", "bob", "carol", "dave", "erin", "frank"}) {
    EXPECT_TRUE(fs::exists(output / name / "results.json")) << name;
    EXPECT_TRUE(fs::exists(output / name / "report/index.html")) << name;
  }
  const std::string carol = readTextFile((output / "carol/results.json").string());
  // The compiler's message is shown once for the stage, without the grading machine's paths.
  const size_t message = carol.find("not C++");
  EXPECT_NE(message, std::string::npos) << carol;
  EXPECT_EQ(carol.find("not C++", message + 1), std::string::npos) << carol;
  EXPECT_EQ(carol.find(fs::absolute(output).parent_path().string()), std::string::npos) << carol;
  EXPECT_NE(carol.find("stage2_nested_ao.cpp:"), std::string::npos) << carol;
  const std::string frank = readTextFile((output / "frank/results.json").string());
  EXPECT_NE(frank.find("missing: stage2_nested_ao.cpp"), std::string::npos) << frank;
  EXPECT_TRUE(fs::exists(output / "index.html"));
}

}  // namespace pathway::test
