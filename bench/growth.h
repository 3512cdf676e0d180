// `pathway_bench growth`: how the cost grows, in one run. Four tables, each also written as CSV
// for scripts/draw_growth.py: every stage against raw Embree on the same rays, 1 against 2
// threads, seconds against samples per pixel, and BVH build time, bytes per triangle and
// primary-ray rate for generated grids of 10k to 10M triangles.
#pragma once

#include <cstdint>
#include <string>

namespace pathway::bench {

struct GrowthOptions {
  std::string scene;   // for the stage, thread and spp tables
  int width = 512;     // image side of the stage and thread tables, and of the grids' ray sets
  int repeats = 10;    // best of this many timed runs: the least disturbed on a shared machine
  std::string outDir;  // empty: print only, write no CSV
  uint64_t maxTriangles = 10'000'000;
};

// The BVH table's smallest grid, and the largest cap --max-triangles accepts (about 10 GiB).
inline constexpr uint64_t kMinGrowthTriangles = 10'000;
inline constexpr uint64_t kMaxGrowthTriangles = 100'000'000;

int benchGrowth(const GrowthOptions& options);

// Measures one grid of 2 n^2 triangles and prints one line of results on stdout. Runs in a
// child process of its own (started by benchGrowth), so that its resident memory starts clean.
int growthGridChild(int gridCells, int width, int repeats);
inline constexpr const char* kGrowthChildMode = "growth-grid-child";

}  // namespace pathway::bench
