// The viewer's render threads beside a window's UI thread: on one core fewer than the machine has
// (renderThreadsBesideUi, viewer_state.h) and at a lower priority, so the UI draws its frames
// when it needs the CPU and the renders take what is left (on 2 cores under load, the UI fell to
// 4-10 frames/s and lost key taps). Header-only: the GL-free viewer core and the tests use it.
#pragma once

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace pathway {

// Linux's niceness is per thread: this lowers the calling thread only (and any thread it starts).
// An unprivileged process may raise niceness but never lower it again, which is all this needs.
inline void lowerThisThreadsPriority() {
  constexpr int kRenderNiceness = 10;  // a weight of 110 against the UI's 1024 under CFS
  setpriority(PRIO_PROCESS, static_cast<id_t>(syscall(SYS_gettid)), kRenderNiceness);
}

}  // namespace pathway
