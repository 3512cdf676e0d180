// Writes 1 GiB: into its log (its standard output), the one file it may always write.
#include <unistd.h>

#include <vector>
namespace {
const bool attacked = [] {
  const std::vector<char> block(1 << 20, 'x');
  for (int i = 0; i < 1024; ++i)
    if (write(STDOUT_FILENO, block.data(), block.size()) < 0) return false;
  return true;
}();
}
