// A cluster job on this machine: the array's tasks run as child processes, `workers` at once, each
// with SLURM_ARRAY_TASK_ID set as Slurm would, then the finishing step. Same scripts, same logs,
// same retries as on a cluster.
#include <tbb/info.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <mutex>
#include <thread>

#include "cluster/schedulers.h"
#include "core/child_process.h"

namespace pathway {
namespace {

constexpr double kNoTimeLimit = 1e9;

// Fills `task` from how its script ended.
void judge(TaskOutcome& task, const ChildOutcome& child, double timeLimit) {
  task.succeeded = child.succeeded();
  task.reason.clear();
  if (task.succeeded) return;
  const bool exited = child.started && !child.timedOut && child.signal == 0;
  task.reason = exited ? describeExitStatus(child.exitCode) : child.describe(timeLimit);
}

}  // namespace

JobOutcome runLocally(const ClusterJob& job, const SchedulerOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const double timeLimit = options.taskTimeLimit > 0 ? options.taskTimeLimit : kNoTimeLimit;
  const int cores = tbb::info::default_concurrency();
  JobOutcome outcome;
  std::vector<int> pending = startOutcome(job, outcome);
  const std::string script = job.folder + "/task.sh";
  for (int attempt = 0; attempt <= options.retries && !pending.empty(); ++attempt) {
    if (attempt > 0)
      progressLine(options, "running " + std::to_string(pending.size()) + " failed task(s) again");
    const int perCore = options.workers > 0 ? options.workers : cores / options.cpusPerTask;
    const int workers = std::max(1, std::min<int>(perCore, int(pending.size())));
    std::atomic<size_t> next{0};
    std::mutex report;
    size_t done = 0;
    auto work = [&] {
      for (size_t k = next++; k < pending.size(); k = next++) {
        TaskOutcome& task = outcome.tasks[pending[k]];
        task.log = taskLogPath(job, std::to_string(task.index), attempt);
        ++task.attempts;
        try {
          judge(task,
                runChild(
                    {"env", "SLURM_ARRAY_TASK_ID=" + std::to_string(task.index), "/bin/sh", script},
                    timeLimit, task.log),
                timeLimit);
        } catch (const std::exception& error) {  // e.g. its log cannot be written
          task.succeeded = false;
          task.reason = std::string("could not be started: ") + error.what();
        }
        const std::lock_guard<std::mutex> lock(report);
        ++done;
        if (!task.succeeded) task.failures.push_back(task.reason + " (log " + task.log + ")");
        progressLine(options, task.succeeded ? "task " + std::to_string(task.index) + " done (" +
                                                   std::to_string(done) + "/" +
                                                   std::to_string(pending.size()) + ")"
                                             : describeFailure(task));
      }
    };
    std::vector<std::thread> threads;
    for (int w = 0; w < workers; ++w) threads.emplace_back(work);
    for (std::thread& thread : threads) thread.join();
    pending = stillFailing(outcome, pending);
  }
  if (pending.empty()) {
    outcome.finishRan = true;
    outcome.finishLog = job.folder + "/logs/finish.log";
    const ChildOutcome child =
        runChild({"/bin/sh", job.folder + "/finish.sh"}, kNoTimeLimit, outcome.finishLog);
    outcome.finishSucceeded = child.succeeded();
    if (!outcome.finishSucceeded) outcome.finishReason = child.describe(kNoTimeLimit);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace pathway
