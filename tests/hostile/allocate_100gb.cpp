// Allocates 100 GB and touches every page (through volatile writes, so that the compiler cannot
// leave the allocation out).
#include <cstdlib>
#include <new>

namespace {
const bool attacked = [] {
  const size_t bytes = size_t(100) << 30;
  volatile char* memory = static_cast<volatile char*>(std::malloc(bytes));
  if (!memory) throw std::bad_alloc();
  for (size_t page = 0; page < bytes; page += 4096) memory[page] = 1;
  return memory[bytes - 4096] == 1;
}();
}  // namespace
