// The two ways a ClusterJob runs (cluster_job.h): on this machine, or through Slurm. Both read the
// scripts runClusterJob wrote into the job's folder and retry failed tasks the same way.
#pragma once

#include <string>
#include <vector>

#include "cluster/cluster_job.h"

namespace pathway {

JobOutcome runLocally(const ClusterJob& job, const SchedulerOptions& options);
JobOutcome runOnSlurm(const ClusterJob& job, const SchedulerOptions& options);

// Fills `outcome` with one entry per task of `job`; returns every task's index (all to run).
std::vector<int> startOutcome(const ClusterJob& job, JobOutcome& outcome);
// The tasks of `ran` that did not succeed (to run again).
std::vector<int> stillFailing(const JobOutcome& outcome, const std::vector<int>& ran);

// Where task `index`'s log goes on its first attempt (0) and on retry `attempt` (1, 2, ...);
// `index` "%a" gives sbatch's pattern for every task of an array.
std::string taskLogPath(const ClusterJob& job, const std::string& index, int attempt);
// Why a script that exited with `status` failed, in words ("killed by signal 9 (Killed)").
std::string describeExitStatus(int status);
// Prints `line` to stderr when progress lines are on.
void progressLine(const SchedulerOptions& options, const std::string& line);

}  // namespace pathway
