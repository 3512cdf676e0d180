// Leaves a daemon behind: double fork, a session of its own, alive for a minute.
#include <sys/prctl.h>
#include <unistd.h>
namespace {
const bool attacked = [] {
  if (fork() == 0) {
    setsid();
    if (fork() == 0) {
      prctl(PR_SET_NAME, "pathway-hostile");
      sleep(60);
    }
    _exit(0);
  }
  return true;
}();
}
