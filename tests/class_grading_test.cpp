// A class graded on one machine: six submissions (correct, a planted bug, one that does not
// compile, one that crashes, one that hangs, one with a missing file) each get their own result,
// and none stops the others. Stage 2 only, to keep the test short.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

TEST(ClassGrading, EverySubmissionGetsItsOwnResult) {
  if (!test::kHaveSolutions) GTEST_SKIP() << "needs solutions/ (the reference stages)";
  const fs::path root = fs::temp_directory_path() / ("pathway_class_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const fs::path submissions = root / "submissions";
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
    ASSERT_EQ(test::runCommand("cp " PATHWAY_SOURCE_DIR "/solutions/*/*.cpp " + folder.string() +
                               " && cd " + folder.string() + " && " + change)
                  .exitCode,
              0)
        << name;
  }
  const test::CommandOutcome outcome = test::runCommand(
      std::string(PATHWAY_BINARY) + " grade -q --stage 2 --time-limit 4 --submissions " +
      submissions.string() + " --output " + (root / "out").string());
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;

  const std::string table = test::readTextFile((root / "out/class.csv").string());
  auto row = [&](const std::string& name) {
    const size_t at = table.find("\n\"" + name + "\",");
    return at == std::string::npos ? "" : table.substr(at + 1, table.find('\n', at + 1) - at - 1);
  };
  EXPECT_NE(row("alice").find("\"alice\",20.0,20.0"), std::string::npos) << table;
  EXPECT_NE(row("alice").find(",\"graded\""), std::string::npos) << table;
  EXPECT_NE(row("bob").find("\"bob\",0.0,20.0"), std::string::npos) << table;
  EXPECT_NE(row("carol").find("\"carol\",0.0,20.0"), std::string::npos) << table;
  EXPECT_NE(row("carol").find("a stage file did not compile"), std::string::npos) << table;
  EXPECT_NE(row("dave").find("a stage crashed"), std::string::npos) << table;
  EXPECT_NE(row("erin").find("ran past its time limit"), std::string::npos) << table;
  EXPECT_NE(row("frank").find("files missing"), std::string::npos) << table;
  for (const std::string name : {"alice", "bob", "carol", "dave", "erin", "frank"}) {
    EXPECT_TRUE(fs::exists(root / "out" / name / "results.json")) << name;
    EXPECT_TRUE(fs::exists(root / "out" / name / "report/index.html")) << name;
  }
  const std::string carol = test::readTextFile((root / "out/carol/results.json").string());
  EXPECT_NE(carol.find("not C++"), std::string::npos) << "the compiler's message is shown";
  const std::string frank = test::readTextFile((root / "out/frank/results.json").string());
  EXPECT_NE(frank.find("missing: stage2_nested_ao.cpp"), std::string::npos) << frank;
  EXPECT_TRUE(fs::exists(root / "out/index.html"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace pathway
