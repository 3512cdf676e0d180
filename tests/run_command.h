// Runs a shell command for the end-to-end tests and captures what it prints; reads the files
// such commands write.
#pragma once

#include <filesystem>
#include <string>

namespace pathway::test {

struct CommandOutcome {
  int exitCode;        // -1 when the command did not exit normally
  std::string output;  // stdout and stderr together
};

CommandOutcome runCommand(const std::string& command);

// An empty folder of its own for the running test: temp/<prefix>_<pid>_<test name>, emptied if it
// was there. The fixture removes it when the test ends.
std::filesystem::path freshTestFolder(const std::string& prefix);

// The whole of a text file ("" when it cannot be read).
std::string readTextFile(const std::string& path);

}  // namespace pathway::test
