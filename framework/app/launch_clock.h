// Milliseconds since the program was launched, for `pathway render --timings`. A launcher that
// wants the dynamic loader's share counted too (pathway_bench startup) puts the CLOCK_MONOTONIC
// time at which it started the program, in nanoseconds, into PATHWAY_LAUNCH_NS; without it the
// clock starts when first read (early in main).
#pragma once

#include <time.h>

#include <cstdint>
#include <cstdlib>
#include <string>

namespace pathway {

inline int64_t monotonicNanoseconds() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return int64_t(now.tv_sec) * 1000000000 + now.tv_nsec;
}

class LaunchClock {
 public:
  LaunchClock() : start_(monotonicNanoseconds()) {
    if (const char* launch = std::getenv("PATHWAY_LAUNCH_NS")) {
      char* end = nullptr;
      const long long value = std::strtoll(launch, &end, 10);
      if (end && *end == '\0' && value > 0 && value <= start_) {
        start_ = value;
        fromLaunch_ = true;
      }
    }
  }
  double milliseconds() const { return (monotonicNanoseconds() - start_) * 1e-6; }
  // "after launch" or "after main() began"
  const char* origin() const { return fromLaunch_ ? "after launch" : "after main() began"; }

 private:
  int64_t start_;
  bool fromLaunch_ = false;
};

}  // namespace pathway
