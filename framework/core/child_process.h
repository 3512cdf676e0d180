// Runs another program (usually this one) as a child process with a time limit, its output
// captured in a file. The grader renders every student stage in a child, so a stage that crashes
// or hangs costs that stage its points and nothing else.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pathway {

struct ChildOutcome {
  bool started = false;
  bool timedOut = false;
  int exitCode = -1;  // when it exited
  int signal = 0;     // when a signal ended it (0: none)
  double seconds = 0.0;
  std::string output;  // stdout and stderr, interleaved, at most the last 64 KiB
  std::string report;  // what it wrote on its report channel (ChildOptions), at most 4 KiB
  // Processes the child started that were still alive when it ended (it left them in its process
  // group, or in a session of their own with setsid): all of them were ended.
  int leftBehind = 0;
  // It wrote more than ChildOptions::folderQuotaBytes below the watched folder and was stopped.
  bool overQuota = false;
  uint64_t quotaBytes = 0;

  bool succeeded() const {
    return started && !timedOut && !overQuota && signal == 0 && exitCode == 0;
  }
  // "exited with status 2", "crashed (signal 11, Segmentation fault)", "ran past its time
  // limit of 60 s", "wrote more than 256 MiB ...", ...
  std::string describe(double timeLimit) const;
};

// How a child starts. A child gets /dev/null as its standard input and no descriptor of this
// process but its output (what the grader has open, a caller's files and pipes, never reaches it),
// unless it keeps them (a grader's --sandbox off, which confines nothing).
struct ChildOptions {
  bool keepDescriptors = false;
  // The child's whole environment ("NAME=value" each); nullopt: this process's. A child that runs
  // untrusted code gets untrustedChildEnvironment(), so that nothing of the grader's environment
  // (tokens, paths) reaches it.
  std::optional<std::vector<std::string>> environment;
  // A folder the child writes in, and the bytes all files below it may hold together; past that
  // the child is stopped (checked every few milliseconds while it runs). 0: not watched.
  std::string watchedFolder;
  uint64_t folderQuotaBytes = 0;
  // The child gets the write end of a pipe as descriptor kChildReportDescriptor, for what it has
  // to say before any untrusted code runs in it (ChildOutcome::report); it closes it after.
  bool reportChannel = false;
};
constexpr int kChildReportDescriptor = 3;

// The environment of a child that runs untrusted code: a fixed PATH, a neutral locale and home,
// and (in a sanitizer build) the sanitizers' own options; nothing else of this process's.
std::vector<std::string> untrustedChildEnvironment();
// How a child that runs untrusted code starts: `confined`, with that environment and none of
// this process's files; unconfined (a grader's --sandbox off, which confines nothing), with both.
ChildOptions untrustedChildOptions(bool confined);

// Runs `arguments` (arguments[0] is the program, found on PATH when it has no '/'), killing it
// (and its children) after `timeLimit` seconds. `outputFile` receives its output. When it ends,
// every process it started is ended too: those still in its process group, and those that left
// it (this process is their subreaper, so they become its children when their parents end).
ChildOutcome runChild(const std::vector<std::string>& arguments, double timeLimit,
                      const std::string& outputFile, const ChildOptions& options = {});

// The path of the running program, for running a part of its own work in a child.
std::string currentExecutable();

// Called first thing in a child that runs untrusted code: it dies with its parent (a stopped
// grader leaves no endless loop behind, though the child has a process group of its own) and
// may write at most `maxFileBytes` to any file (its log included).
void limitThisChild(uint64_t maxFileBytes);

}  // namespace pathway
