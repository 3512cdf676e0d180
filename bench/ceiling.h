// `pathway_bench ceiling`: the framework's stage5@ref against the minimal path tracer on raw
// Embree (raw_path_tracer.h), the same image in one run, timed in turns. The goal it measures:
// stage5@ref delivers at least 0.85 of the raw tracer's rays/s.
#pragma once

#include <cstdint>
#include <string>

namespace pathway::bench {

struct CeilingOptions {
  std::string scene;
  int width = 256;  // height from the camera's aspect ratio
  uint32_t samplesPerPixel = 64;
  int repeats = 3;  // best of this many renders each, interleaved raw / framework
};

// Prints the table; returns 1 when the two images' global means differ by more than 1 % (or, when
// noise alone is larger, by more than 4 standard errors).
int benchCeiling(const CeilingOptions& options);

}  // namespace pathway::bench
