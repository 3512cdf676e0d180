// Writes outside its output: a file of its own, and over another student's submission.
#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  std::ofstream(hostile::setting("PATHWAY_HOSTILE_DROP") + "/written") << "was here\n";
  std::ofstream(hostile::setting("PATHWAY_HOSTILE_SECRET"), std::ios::trunc) << "overwritten\n";
  return true;
}();
}
