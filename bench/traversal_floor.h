// `pathway_bench floor`: how fast the wavefront references of stages 2, 3 and 5 could be if
// nothing but Embree's traversal cost anything. It logs every ray `stageN@fast` traces for one
// image and replays exactly those rays through raw Embree in the same queries (its 16-ray
// packets; no shading, no sampling, no film), into Pathway's robust BVH and into Embree's cheapest
// (non-robust) one, and sets the times beside the render's own. The peers benchmark divides them by
// Mitsuba's render time.
#pragma once

#include <cstdint>
#include <string>

namespace pathway::bench {

struct FloorOptions {
  std::string scene;
  int width = 256;  // the peers image, square
  uint32_t samplesPerPixel = 64;
  int repeats = 3;        // best of this many, render and replays in turns
  int viewerWidth = 640;  // the viewer's reference pane, one sample per pixel per image
  int viewerHeight = 360;
};

// Prints the tables and a last line `floor: render=S robust=S non-robust=S` (stage 5's seconds,
// for bench/peers/peers.py). Returns 0; throws when the replay does not find what the rays find.
int benchFloor(const FloorOptions& options);

}  // namespace pathway::bench
