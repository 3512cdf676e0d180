// Reaches another process without kill(): makes its parent the owner of a pipe (F_SETOWN), so
// that the kernel sends it SIGIO, and lowers the priority of every process of its user
// (setpriority with PRIO_USER); then says which it could do.
#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {
const bool attacked = []() -> bool {
  int ends[2] = {-1, -1};
  const bool owner = pipe(ends) == 0 && fcntl(ends[0], F_SETOWN, getppid()) == 0;
  const bool user = setpriority(PRIO_USER, 0, 0) == 0;  // its own priority: harms nobody here
  std::printf("signal_owner: F_SETOWN %s, PRIO_USER %s\n", owner ? "accepted" : "refused",
              user ? "accepted" : "refused");
  std::fflush(stdout);
  std::abort();  // so that what it printed is in the report
}();
}  // namespace
