// A job for many machines: an array of tasks, each a chunk of work (a range of samples, a few
// submissions), and a finishing step that runs once all of them succeeded (merge the parts, write
// the class table). The same job runs on a Slurm cluster (an sbatch array plus a dependent job) or
// on this machine (N worker processes), from the same two shell scripts in the job's folder:
//
//   <folder>/task.sh     array task $SLURM_ARRAY_TASK_ID: one `case` branch per task
//   <folder>/finish.sh   the finishing step
//   <folder>/logs/       task-<i>.log (and task-<i>.retry1.log ...), finish.log
#pragma once

#include <string>
#include <vector>

namespace pathway {

struct ClusterJob {
  std::string name;    // the Slurm job name, e.g. "pathway-render"
  std::string folder;  // absolute; on a cluster it must be on storage every node sees
  // The shell lines of each task (task i runs tasks[i] under `set -e`) and of the finishing step.
  std::vector<std::vector<std::string>> tasks;
  std::vector<std::string> finish;
};

enum class SchedulerKind { Local, Slurm };

struct SchedulerOptions {
  SchedulerKind kind = SchedulerKind::Local;
  int workers = 0;             // local: tasks at once (0: cores / cpusPerTask)
  double taskTimeLimit = 0.0;  // seconds a task may run (0: no limit); Slurm's --time
  int cpusPerTask = 1;         // Slurm's --cpus-per-task
  int maxRunning = 0;          // Slurm: array tasks at once (0: as many as the cluster gives)
  std::string partition, account;
  std::vector<std::string> sbatchArguments;  // passed to every sbatch as they are
  int retries = 1;                           // a failed task runs again this many times
  bool progress = true;                      // progress lines on stderr
  double pollSeconds = 0.2;                  // Slurm: how often to ask the controller
};

struct TaskOutcome {
  int index = 0;
  bool succeeded = false;
  std::string reason;  // for a failure: "exited with status 1", "killed by signal 9", ...
  std::string log;     // the last attempt's log
  std::vector<std::string> failures;  // every failed attempt: "<reason> (log <path>)"
  int attempts = 0;
};

struct JobOutcome {
  std::vector<TaskOutcome> tasks;
  bool finishRan = false;  // the finishing step ran (all tasks succeeded)
  bool finishSucceeded = false;
  std::string finishLog;
  std::string finishReason;
  double seconds = 0.0;  // wall time from submission to the end

  std::vector<const TaskOutcome*> failedTasks() const;
};

// Writes the scripts, runs the job with the scheduler, follows it (progress on stderr) and returns
// what happened to every task. A task that fails is run again up to `retries` times; when one
// still fails the finishing step does not run, and every other task's work stays where it is.
// Throws PathwayError when the job cannot be started (no sbatch, a refused submission, ...).
JobOutcome runClusterJob(const ClusterJob& job, const SchedulerOptions& options);

// `text` as one shell word.
std::string shellQuote(const std::string& text);

// "task 3 was cancelled (...) (log <folder>/logs/task-3.log)": a failed task in one line.
std::string describeFailure(const TaskOutcome& task);

}  // namespace pathway
