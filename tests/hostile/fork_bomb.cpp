// A fork bomb, bounded (64 processes, each alive for a minute) so that the unsandboxed control
// run harms nothing.
#include <sys/prctl.h>
#include <unistd.h>
namespace {
const bool attacked = [] {
  for (int i = 0; i < 64; ++i)
    if (fork() == 0) {
      prctl(PR_SET_NAME, "pathway-hostile");
      sleep(60);
      _exit(0);
    }
  return true;
}();
}
