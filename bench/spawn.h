// Running a program as a child and reading what it prints: the growth table measures each grid in
// a fresh process, the start-up table times whole `pathway` commands.
#pragma once

#include <string>
#include <vector>

#include "core/child_process.h"

namespace pathway::bench {

struct SpawnedRun {
  ChildOutcome outcome;    // exit status or signal; `output` holds the child's stdout
  double seconds = 0.0;    // from just before the spawn to the child's exit
  long long launchNs = 0;  // CLOCK_MONOTONIC at the spawn, also passed as PATHWAY_LAUNCH_NS
};

// Runs `arguments` (arguments[0] a path), stdout captured, stderr inherited, with
// PATHWAY_LAUNCH_NS set to the launch time. Throws PathwayError when it cannot start.
SpawnedRun spawnCapturingStdout(const std::vector<std::string>& arguments);

}  // namespace pathway::bench
