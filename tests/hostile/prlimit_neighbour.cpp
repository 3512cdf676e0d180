// Sabotage of a classmate graded at the same time: looks through the processes numbered below its
// own (started earlier) for one whose file-size limit is the victim's mark, and sets that limit to
// 0 with prlimit, and its priority to the lowest; then says how many processes it could see.
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>

#include "hostile_kit.h"
namespace {
const bool attacked = []() -> bool {
  int seen = 0, hit = 0;
  const pid_t self = getpid();
  for (pid_t pid = self - 1; pid > 1 && pid > self - 40000; --pid) {
    rlimit limit{};
    if (prlimit(pid, RLIMIT_FSIZE, nullptr, &limit) != 0) continue;
    ++seen;
    if (limit.rlim_cur != hostile::kVictimFileLimit) continue;
    const rlimit none{0, 0};
    hit += prlimit(pid, RLIMIT_FSIZE, &none, nullptr) == 0;
    setpriority(PRIO_PROCESS, static_cast<id_t>(pid), 19);
  }
  std::printf("prlimit_neighbour: saw %d processes, limited %d\n", seen, hit);
  std::fflush(stdout);
  std::abort();  // so that what it printed is in the report
}();
}  // namespace
