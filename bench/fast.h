// `pathway_bench fast`: the wavefront references (stageN@fast) against the single-ray ones
// (stageN@ref) on the same image, timed in turns, with their agreement; then the commands that
// use them by default, `pathway grade --make-references` and `--calibrate`, timed as whole
// processes with and without --single-ray. scripts/bench fast adds the viewer's reference pane.
#pragma once

#include <cstdint>
#include <string>

namespace pathway::bench {

struct FastOptions {
  std::string scene;
  int width = 256;  // height from the camera's aspect ratio
  uint32_t samplesPerPixel = 64;
  int repeats = 3;               // best of this many renders each, in turns
  int calibrationSeeds = 100;    // pathway grade --calibrate N (0: leave it out)
  uint32_t agreementSpp = 4096;  // the mean agreement render (64 pixels wide)
};

// Prints the tables; returns 1 when a wavefront image differs from the single-ray one by more
// than 0.1 % in its mean.
int benchFast(const FastOptions& options);

}  // namespace pathway::bench
