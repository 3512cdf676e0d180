#include "cluster/cluster_job.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "cluster/schedulers.h"
#include "core/error.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

void writeScript(const fs::path& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  out.close();
  if (!out) throw PathwayError(path.string() + ": cannot write the job's script");
  fs::permissions(path, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                            fs::perms::others_read | fs::perms::others_exec);
}

// POSIX sh (Slurm runs batch scripts with /bin/sh, dash on Debian): no bash features.
std::string taskScript(const ClusterJob& job) {
  std::string text = "#!/bin/sh\n# Written by `pathway cluster`: task $SLURM_ARRAY_TASK_ID of " +
                     std::to_string(job.tasks.size()) + " of the job '" + job.name +
                     "'.\nset -e\ncase \"$SLURM_ARRAY_TASK_ID\" in\n";
  for (size_t i = 0; i < job.tasks.size(); ++i) {
    text += std::to_string(i) + ")\n";
    for (const std::string& line : job.tasks[i]) text += "  " + line + "\n";
    text += "  ;;\n";
  }
  text += "*)\n  echo \"task.sh: no task '$SLURM_ARRAY_TASK_ID' (0 to " +
          std::to_string(job.tasks.size() - 1) + ")\" >&2\n  exit 2\n  ;;\nesac\n";
  return text;
}

std::string finishScript(const ClusterJob& job) {
  std::string text =
      "#!/bin/sh\n# Written by `pathway cluster`: runs once every task of the job '" + job.name +
      "' succeeded.\nset -e\n";
  for (const std::string& line : job.finish) text += line + "\n";
  return text;
}

}  // namespace

std::vector<const TaskOutcome*> JobOutcome::failedTasks() const {
  std::vector<const TaskOutcome*> failed;
  for (const TaskOutcome& task : tasks)
    if (!task.succeeded) failed.push_back(&task);
  return failed;
}

std::vector<int> startOutcome(const ClusterJob& job, JobOutcome& outcome) {
  outcome.tasks.resize(job.tasks.size());
  std::vector<int> all;
  for (size_t i = 0; i < job.tasks.size(); ++i) {
    outcome.tasks[i].index = static_cast<int>(i);
    all.push_back(static_cast<int>(i));
  }
  return all;
}

std::vector<int> stillFailing(const JobOutcome& outcome, const std::vector<int>& ran) {
  std::vector<int> failed;
  for (int index : ran)
    if (!outcome.tasks[index].succeeded) failed.push_back(index);
  return failed;
}

std::string shellQuote(const std::string& text) {
  if (!text.empty() && text.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                              "0123456789@%+=:,./-_") == std::string::npos)
    return text;
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string taskLogPath(const ClusterJob& job, const std::string& index, int attempt) {
  const std::string retry = attempt == 0 ? "" : ".retry" + std::to_string(attempt);
  return job.folder + "/logs/task-" + index + retry + ".log";
}

std::string describeExitStatus(int status) {
  // A shell reports a command that a signal ended as 128 + the signal.
  if (status > 128 && status < 128 + 65)
    return "exited with status " + std::to_string(status) + ": killed by signal " +
           std::to_string(status - 128) + " (" + strsignal(status - 128) + ")";
  return "exited with status " + std::to_string(status);
}

std::string describeFailure(const TaskOutcome& task) {
  std::string text =
      "task " + std::to_string(task.index) + " " + task.reason + " (log " + task.log + ")";
  if (task.attempts > 1) text += " after " + std::to_string(task.attempts) + " attempts";
  return text;
}

void progressLine(const SchedulerOptions& options, const std::string& line) {
  if (!options.progress) return;
  std::fprintf(stderr, "cluster: %s\n", line.c_str());
  std::fflush(stderr);
}

JobOutcome runClusterJob(const ClusterJob& job, const SchedulerOptions& options) {
  if (job.tasks.empty()) throw PathwayError("internal: a cluster job without tasks");
  const fs::path folder(job.folder);
  fs::create_directories(folder / "logs");
  writeScript(folder / "task.sh", taskScript(job));
  writeScript(folder / "finish.sh", finishScript(job));
  return options.kind == SchedulerKind::Slurm ? runOnSlurm(job, options) : runLocally(job, options);
}

}  // namespace pathway
