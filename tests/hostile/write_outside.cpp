// Writes outside its output: a file of its own, and over another student's submission.
#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  std::ofstream(hostile::drop() + "/written") << "was here\n";
  std::ofstream(hostile::secret(), std::ios::trunc) << "overwritten\n";
  return true;
}();
}
