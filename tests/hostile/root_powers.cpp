// Says who it runs as, and tries what only root (or a process with capabilities) may: raise its
// own priority, raise its hard limit on open files, and set the host name (to what it is).
#include <sys/resource.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace {
const bool attacked = []() -> bool {
  std::printf("root_powers: uid=%d euid=%d\n", static_cast<int>(getuid()),
              static_cast<int>(geteuid()));
  const bool priority = setpriority(PRIO_PROCESS, 0, -5) == 0;
  rlimit files{};
  getrlimit(RLIMIT_NOFILE, &files);
  const rlimit more{files.rlim_max + 1, files.rlim_max + 1};
  const bool limit = setrlimit(RLIMIT_NOFILE, &more) == 0;
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  const bool host = sethostname(name, std::char_traits<char>::length(name)) == 0;
  std::printf("root_powers: priority %s, limit %s, hostname %s\n", priority ? "raised" : "refused",
              limit ? "raised" : "refused", host ? "set" : "refused");
  std::fflush(stdout);
  std::abort();  // so that what it printed is in the report
}();
}  // namespace
