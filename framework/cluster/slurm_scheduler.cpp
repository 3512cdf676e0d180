// A cluster job on Slurm: one sbatch array for the tasks and one job that depends on it with
// afterok (and --kill-on-invalid-dep=yes, or it would wait forever once a task fails). The job is
// followed by asking the controller (scontrol) every `pollSeconds`: `sbatch --wait` polls at 2,
// 8, then 32 s, far too coarse for jobs of seconds. Failed tasks go in again as a new array with a
// new dependent job.
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include "cluster/schedulers.h"
#include "core/child_process.h"
#include "core/error.h"

namespace pathway {
namespace {

constexpr double kCommandTimeLimit = 60.0;

// Runs a Slurm command; returns its output, or throws naming the command and what it said.
std::string slurmCommand(const ClusterJob& job, const std::vector<std::string>& arguments) {
  const ChildOutcome child =
      runChild(arguments, kCommandTimeLimit, job.folder + "/logs/.slurm-command.out");
  if (!child.succeeded()) {
    std::string command;
    for (const std::string& argument : arguments)
      command += (command.empty() ? "" : " ") + argument;
    throw PathwayError(command + ": " + child.describe(kCommandTimeLimit) + ": " + child.output);
  }
  return child.output;
}

// Slurm's --time as minutes:seconds, rounded up to whole seconds.
std::string slurmTime(double seconds) {
  const long total = static_cast<long>(std::ceil(seconds));
  return std::to_string(total / 60) + ":" + (total % 60 < 10 ? "0" : "") +
         std::to_string(total % 60);
}

// What every sbatch gets. --no-requeue: a task that fails is retried by us, in a new array, never
// also by Slurm (two runs would write the same part).
std::vector<std::string> commonArguments(const ClusterJob& job, const SchedulerOptions& options) {
  std::vector<std::string> arguments = {"sbatch", "--parsable", "--no-requeue",
                                        "--chdir=" + job.folder};
  if (!options.partition.empty()) arguments.push_back("--partition=" + options.partition);
  if (!options.account.empty()) arguments.push_back("--account=" + options.account);
  for (const std::string& extra : options.sbatchArguments) arguments.push_back(extra);
  return arguments;
}

// The job id sbatch --parsable prints ("123" or "123;cluster"), on a line of its own after any
// warnings (its output and errors arrive together).
std::string jobId(const std::string& output) {
  std::istringstream lines(output);
  std::string id;
  for (std::string line; std::getline(lines, line);) {
    line = line.substr(0, line.find(';'));
    if (!line.empty() && line.find_first_not_of("0123456789") == std::string::npos) id = line;
  }
  if (id.empty()) throw PathwayError("sbatch printed no job id: " + output);
  return id;
}

std::string submitArray(const ClusterJob& job, const SchedulerOptions& options,
                        const std::vector<int>& indices, int attempt) {
  std::string list;
  for (int index : indices) list += (list.empty() ? "" : ",") + std::to_string(index);
  if (options.maxRunning > 0) list += "%" + std::to_string(options.maxRunning);
  std::vector<std::string> arguments = commonArguments(job, options);
  if (options.taskTimeLimit > 0) arguments.push_back("--time=" + slurmTime(options.taskTimeLimit));
  arguments.insert(arguments.end(),
                   {"--array=" + list, "--job-name=" + job.name,
                    "--cpus-per-task=" + std::to_string(options.cpusPerTask),
                    "--output=" + taskLogPath(job, "%a", attempt), job.folder + "/task.sh"});
  return jobId(slurmCommand(job, arguments));
}

std::string submitFinish(const ClusterJob& job, const SchedulerOptions& options,
                         const std::string& arrayId) {
  std::vector<std::string> arguments = commonArguments(job, options);
  arguments.insert(arguments.end(),
                   {"--job-name=" + job.name + "-finish", "--dependency=afterok:" + arrayId,
                    "--kill-on-invalid-dep=yes", "--output=" + job.folder + "/logs/finish.log",
                    job.folder + "/finish.sh"});
  return jobId(slurmCommand(job, arguments));
}

// One record of `scontrol -o show job`: its Key=Value words.
using Record = std::map<std::string, std::string>;

// The job's records; none once the controller has forgotten it (MinJobAge after it ended).
std::vector<Record> showJob(const ClusterJob& job, const std::string& id) {
  std::vector<Record> records;
  const ChildOutcome child = runChild({"scontrol", "-o", "show", "job", id}, kCommandTimeLimit,
                                      job.folder + "/logs/.slurm-command.out");
  if (!child.succeeded()) {
    if (child.output.find("Invalid job id") != std::string::npos) return records;
    throw PathwayError("scontrol show job " + id + ": " + child.describe(kCommandTimeLimit) + ": " +
                       child.output);
  }
  std::istringstream lines(child.output);
  for (std::string line; std::getline(lines, line);) {
    Record record;
    std::istringstream words(line);
    for (std::string word; words >> word;) {
      const size_t equals = word.find('=');
      if (equals != std::string::npos) record[word.substr(0, equals)] = word.substr(equals + 1);
    }
    if (record.count("JobState")) records.push_back(std::move(record));
  }
  return records;
}

bool isFinal(const std::string& state) {
  static const std::set<std::string> running = {
      "PENDING",      "CONFIGURING", "RUNNING",      "COMPLETING", "SUSPENDED",
      "REQUEUED",     "RESIZING",    "SIGNALING",    "STAGE_OUT",  "STOPPED",
      "REQUEUE_HOLD", "REQUEUE_FED", "RESV_DEL_HOLD"};
  return !running.count(state);
}

std::string describeState(const Record& record) {
  const std::string& state = record.at("JobState");
  const std::string exit = record.count("ExitCode") ? record.at("ExitCode") : "0:0";
  const int status = std::atoi(exit.c_str());
  const int signal = std::atoi(exit.substr(exit.find(':') + 1).c_str());
  if (state == "FAILED")
    return signal != 0 ? "was killed by signal " + std::to_string(signal)
                       : describeExitStatus(status);
  if (state == "TIMEOUT") return "ran past its time limit (TIMEOUT)";
  if (state == "CANCELLED") return "was cancelled (CANCELLED: scancel, or an administrator)";
  if (state == "OUT_OF_MEMORY") return "ran out of memory (OUT_OF_MEMORY)";
  if (state == "NODE_FAIL") return "lost its node (NODE_FAIL)";
  return "ended " + state;
}

// Follows one array (the tasks in `indices`) and its dependent job until both are over; fills
// the tasks' outcomes. Returns the dependent job's final record.
Record follow(const ClusterJob& job, const SchedulerOptions& options, const std::string& arrayId,
              const std::string& finishId, const std::vector<int>& indices, int attempt,
              JobOutcome& outcome) {
  std::string lastLine;
  std::set<int> reported;
  while (true) {
    std::map<std::string, int> counts;
    bool over = true;
    for (const Record& record : showJob(job, arrayId)) {
      const std::string& state = record.at("JobState");
      const std::string tasks = record.count("ArrayTaskId") ? record.at("ArrayTaskId") : "";
      // Pending tasks come as one record "2-7" (or "2,5"): count them all as waiting.
      if (tasks.find_first_not_of("0123456789") != std::string::npos || tasks.empty()) {
        over = false;
        continue;
      }
      const int index = std::atoi(tasks.c_str());
      if (index < 0 || index >= int(outcome.tasks.size()))
        throw PathwayError("job " + arrayId + " has a task " + tasks + " it was not given");
      TaskOutcome& task = outcome.tasks[index];
      if (!isFinal(state)) {
        ++counts[state == "PENDING" ? "waiting" : "running"];
        over = false;
        continue;
      }
      ++counts[state == "COMPLETED" ? "done" : "failed"];
      if (reported.insert(index).second) {
        ++task.attempts;
        task.succeeded = state == "COMPLETED";
        task.log = taskLogPath(job, std::to_string(index), attempt);
        if (!task.succeeded) {
          task.reason = describeState(record);
          task.failures.push_back(task.reason + " (log " + task.log + ")");
          progressLine(options, describeFailure(task));
        }
      }
    }
    // A pending range is one record for many tasks: what is not accounted for is waiting.
    const int accounted = counts["done"] + counts["failed"] + counts["running"];
    counts["waiting"] = int(indices.size()) - accounted;
    const std::string line =
        std::to_string(indices.size()) + " task(s): " + std::to_string(counts["done"]) + " done, " +
        std::to_string(counts["running"]) + " running, " + std::to_string(counts["waiting"]) +
        " waiting, " + std::to_string(counts["failed"]) + " failed";
    if (line != lastLine) progressLine(options, "job " + arrayId + ": " + line);
    lastLine = line;
    if (over && reported.size() == indices.size()) {
      const std::vector<Record> finish = showJob(job, finishId);
      if (!finish.empty() && isFinal(finish.front().at("JobState"))) return finish.front();
      // Forgotten by the controller: cancelled long ago when a task failed.
      if (finish.empty()) return {{"JobState", counts["failed"] > 0 ? "CANCELLED" : "UNKNOWN"}};
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(options.pollSeconds));
  }
}

}  // namespace

JobOutcome runOnSlurm(const ClusterJob& job, const SchedulerOptions& options) {
  if (runChild({"sbatch", "--version"}, kCommandTimeLimit, job.folder + "/logs/.slurm-command.out")
          .exitCode != 0)
    throw PathwayError(
        "sbatch was not found or does not run: is this a Slurm login node? (without a cluster, "
        "use --scheduler local)");
  const auto start = std::chrono::steady_clock::now();
  JobOutcome outcome;
  std::vector<int> pending = startOutcome(job, outcome);
  for (int attempt = 0; attempt <= options.retries && !pending.empty(); ++attempt) {
    const std::string arrayId = submitArray(job, options, pending, attempt);
    std::string finishId;
    try {
      finishId = submitFinish(job, options, arrayId);
    } catch (const PathwayError&) {
      // No task may run without its last step: take the array back.
      runChild({"scancel", arrayId}, kCommandTimeLimit, job.folder + "/logs/.slurm-command.out");
      throw;
    }
    progressLine(options, "submitted array job " + arrayId + " (" + std::to_string(pending.size()) +
                              " task(s)) and job " + finishId + " after it (afterok); logs in " +
                              job.folder + "/logs");
    const Record finish = follow(job, options, arrayId, finishId, pending, attempt, outcome);
    pending = stillFailing(outcome, pending);
    if (pending.empty()) {
      outcome.finishRan = true;
      outcome.finishLog = job.folder + "/logs/finish.log";
      outcome.finishSucceeded = finish.at("JobState") == "COMPLETED";
      if (!outcome.finishSucceeded) outcome.finishReason = describeState(finish);
    } else if (attempt < options.retries) {
      progressLine(options, "running " + std::to_string(pending.size()) +
                                " failed task(s) again (job " + finishId +
                                " was cancelled with them)");
    }
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

}  // namespace pathway
