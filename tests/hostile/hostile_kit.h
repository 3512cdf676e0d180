// What the hostile stages share. The grader hands a child nothing of its own environment, so the
// attacks cannot be told at run time where to look: the test and the stages agree on a fixed
// folder at build time (PATHWAY_HOSTILE_WORK, tests/hostile/CMakeLists.txt), which the test fills
// before each run: drop/ for loot, alice/ for another student's file, port for the listener.
// Each attack runs in a static initializer, so it runs as the library loads, before the grader
// renders anything.
#pragma once

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace hostile {

inline std::string work() {
  return PATHWAY_HOSTILE_WORK;
}
inline std::string drop() {
  return work() + "/drop";
}
inline std::string secret() {
  return work() + "/alice/stage1_filtering.cpp";
}
inline std::string references() {
  return PATHWAY_HOSTILE_REFERENCES;
}
inline std::string reference() {
  return references() + "/stage1-cornell-box.exr";
}

// What the attacks and the test agree on besides the folder.
constexpr int kSharedKey = 0x50617468;                 // System V shared memory ("Path")
constexpr int kQueueKey = 0x50617469;                  // a System V message queue
constexpr int kSemaphoreKey = 0x5061746a;              // a System V semaphore set
constexpr unsigned long kVictimFileLimit = 123456789;  // the victim's mark: its file-size limit
constexpr const char* kSecretVariable = "PATHWAY_HOSTILE_GRADER_TOKEN";

inline std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Copies `from` into the drop folder as `name`: the loot the test looks for.
inline void steal(const std::string& from, const std::string& name) {
  std::ifstream in(from, std::ios::binary);
  if (!in) return;
  std::ofstream(drop() + "/" + name, std::ios::binary) << readFile(from);
}

// The child's own --output folder, from its command line (/proc/self stays readable).
inline std::string outputFolder() {
  const std::string line = readFile("/proc/self/cmdline");
  const std::string flag = std::string("--output") + '\0';
  const size_t at = line.find(flag);
  if (at == std::string::npos) return "";
  const size_t start = at + flag.size();
  return line.substr(start, line.find('\0', start) - start);
}

}  // namespace hostile
