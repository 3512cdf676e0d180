// What the hostile stages share (tests/hostile_test.cpp sets the environment): where to drop
// what they steal, what to steal, and the port to call. Each attack runs in a static
// initializer, so it runs as the library loads, before the grader renders anything.
#pragma once

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace hostile {

inline std::string setting(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

// Copies `from` into the drop folder as `name`: the loot the test looks for.
inline void steal(const std::string& from, const std::string& name) {
  std::ifstream in(from, std::ios::binary);
  if (!in) return;
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::ofstream(setting("PATHWAY_HOSTILE_DROP") + "/" + name, std::ios::binary) << bytes;
}

}  // namespace hostile
