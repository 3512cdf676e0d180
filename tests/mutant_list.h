// The grader's mutant suite as tests/mutants/CMakeLists.txt lists it (PATHWAY_MUTANT_LIST, one
// "name|stage|expect[:cause]|library|description" line per planted bug): for the tests that grade
// the bugs and the ones that load their libraries.
#pragma once

#ifdef PATHWAY_MUTANT_LIST

#include <fstream>
#include <ostream>
#include <sstream>
#include <string>
#include <vector>

namespace pathway::test {

struct Mutant {
  std::string name;
  int stage = 0;
  std::string expect;  // fail, pass, crash, crash-one, hang or hang-one
  // for fail: the likely cause the bug should read as (scripts/mutant-causes); for pass,
  // "noisier": a valid estimator with more noise, which a note must point out
  std::string cause;
  std::string library;
  std::string description;
};

inline std::vector<Mutant> mutants() {
  std::vector<Mutant> list;
  std::ifstream in(PATHWAY_MUTANT_LIST);
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> fields;
    std::stringstream parts(line);
    for (std::string field; std::getline(parts, field, '|');) fields.push_back(field);
    if (fields.size() != 5) continue;
    const size_t colon = fields[2].find(':');
    list.push_back({fields[0], std::stoi(fields[1]), fields[2].substr(0, colon),
                    colon == std::string::npos ? "" : fields[2].substr(colon + 1), fields[3],
                    fields[4]});
  }
  return list;
}

// The planted bugs of one stage.
inline std::vector<Mutant> mutantsOfStage(int stage) {
  std::vector<Mutant> list;
  for (const Mutant& mutant : mutants())
    if (mutant.stage == stage) list.push_back(mutant);
  return list;
}

inline void PrintTo(const Mutant& mutant, std::ostream* out) {
  *out << mutant.name << " (" << mutant.description << ")";
}

}  // namespace pathway::test

#endif  // PATHWAY_MUTANT_LIST
