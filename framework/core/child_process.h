// Runs another program (usually this one) as a child process with a time limit, its output
// captured in a file. The grader renders every student stage in a child, so a stage that crashes
// or hangs costs that stage its points and nothing else.
#pragma once

#include <cstdint>
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
  // Processes the child started that were still alive when it ended (it left them in its process
  // group, or in a session of their own with setsid): all of them were ended.
  int leftBehind = 0;

  bool succeeded() const { return started && !timedOut && signal == 0 && exitCode == 0; }
  // "exited with status 2", "crashed (signal 11, Segmentation fault)", "ran past its time
  // limit of 60 s", ...
  std::string describe(double timeLimit) const;
};

// Runs `arguments` (arguments[0] is the program, found on PATH when it has no '/'), killing it
// (and its children) after `timeLimit` seconds. `outputFile` receives its output. When it ends,
// every process it started is ended too: those still in its process group, and those that left
// it (this process is their subreaper, so they become its children when their parents end).
ChildOutcome runChild(const std::vector<std::string>& arguments, double timeLimit,
                      const std::string& outputFile);

// The path of the running program, for running a part of its own work in a child.
std::string currentExecutable();

// Called first thing in a child that runs untrusted code: it dies with its parent (a stopped
// grader leaves no endless loop behind, though the child has a process group of its own) and
// may write at most `maxFileBytes` to any file (its log included).
void limitThisChild(uint64_t maxFileBytes);

}  // namespace pathway
