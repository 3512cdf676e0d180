// `pathway_bench startup`: how long a `pathway` command takes to start. Runs the program several
// times as a child and reports the medians: the whole of `pathway render --help`, and for a stage-5
// render of the Cornell box (256x256, 64 spp) when its first ray was traced, when its last was,
// and when the process had ended, all from the moment it was launched (`--timings`).
#pragma once

namespace pathway::bench {

int benchStartup(int repeats);

}  // namespace pathway::bench
