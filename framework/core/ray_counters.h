// Ray and sample counters. Each tile keeps its own and they are summed in a fixed order, so the
// totals are exact and the same for any thread count.
#pragma once

#include <cstdint>

namespace pathway {

enum class RayKind { Primary, Secondary, Shadow };

struct RayCounters {
  uint64_t primary = 0;         // camera rays
  uint64_t secondary = 0;       // rays that look for the closest hit after a bounce (AO, indirect)
  uint64_t shadow = 0;          // rays that only ask "is anything in the way?"
  uint64_t samples = 0;         // camera samples splatted into the film
  uint64_t invalidSamples = 0;  // non-finite radiance samples, counted and dropped

  void count(RayKind kind) {
    switch (kind) {
      case RayKind::Primary:
        ++primary;
        break;
      case RayKind::Secondary:
        ++secondary;
        break;
      case RayKind::Shadow:
        ++shadow;
        break;
    }
  }
  uint64_t totalRays() const { return primary + secondary + shadow; }

  RayCounters& operator+=(const RayCounters& other) {
    primary += other.primary;
    secondary += other.secondary;
    shadow += other.shadow;
    samples += other.samples;
    invalidSamples += other.invalidSamples;
    return *this;
  }
};

}  // namespace pathway
