#include "core/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "core/error.h"

extern char** environ;

namespace pathway {
namespace {

// The last `limit` bytes of a file, read from there (a child may have written gigabytes).
std::string lastBytes(const std::string& path, size_t limit) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  const std::streamoff size = in.tellg();
  if (size <= 0) return "";
  const std::streamoff start = std::max<std::streamoff>(0, size - std::streamoff(limit));
  in.seekg(start);
  std::string text(static_cast<size_t>(size - start), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  return start > 0 ? "..." + text : text;
}

// The children runChild is waiting for, in any thread: never taken for strays.
std::mutex liveChildrenMutex;
std::set<pid_t> liveChildren;

// The parent and process group of `pid`, from /proc/PID/stat (after the command's parentheses).
bool parentAndGroup(pid_t pid, pid_t& parent, pid_t& group) {
  std::ifstream in("/proc/" + std::to_string(pid) + "/stat");
  std::string stat;
  if (!std::getline(in, stat)) return false;
  const size_t close = stat.rfind(')');
  if (close == std::string::npos) return false;
  std::istringstream fields(stat.substr(close + 1));
  char state = 0;
  return static_cast<bool>(fields >> state >> parent >> group);
}

// Ends the processes a child left behind: its process group, and the orphans that were handed to
// this process as their subreaper (they left the group with setsid, so their group is not ours).
// Children of this process that share its group (started by others, e.g. popen) are left alone.
int endLeftBehind(pid_t child) {
  // The group first; its members, once dead, are handed over too and reaped below.
  if (::kill(-child, SIGKILL) == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
  int ended = 0;
  const pid_t self = ::getpid(), ownGroup = ::getpgrp();
  for (int round = 0; round < 100; ++round) {  // killing one may hand over its own children
    std::vector<pid_t> strays;
    {
      const std::lock_guard<std::mutex> lock(liveChildrenMutex);
      std::error_code error;
      for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
        const std::string name = entry.path().filename().string();
        if (name.empty() || name.find_first_not_of("0123456789") != std::string::npos) continue;
        const pid_t pid = std::stoi(name);
        pid_t parent = 0, group = 0;
        if (parentAndGroup(pid, parent, group) && parent == self && group != ownGroup &&
            !liveChildren.count(pid))
          strays.push_back(pid);
      }
    }
    if (strays.empty()) break;
    for (pid_t pid : strays) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, nullptr, 0);
      ++ended;
    }
  }
  return ended;
}

}  // namespace

std::string ChildOutcome::describe(double timeLimit) const {
  if (!started) return "could not be started";
  if (timedOut) {
    std::ostringstream text;
    text << "ran past its time limit of " << timeLimit << " s and was stopped";
    return text.str();
  }
  if (signal != 0)
    return "crashed (signal " + std::to_string(signal) + ", " + strsignal(signal) + ")";
  return "exited with status " + std::to_string(exitCode);
}

ChildOutcome runChild(const std::vector<std::string>& arguments, double timeLimit,
                      const std::string& outputFile) {
  ChildOutcome outcome;
  const int output =
      ::open(outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644);
  if (output < 0) throw PathwayError(outputFile + ": cannot write: " + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, output, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, output, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // Its own process group, so a timeout stops the child and anything it started.
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP);
  posix_spawnattr_setpgroup(&attributes, 0);
  // Orphans of what the child starts come to this process, not to init, so they can be ended.
  ::prctl(PR_SET_CHILD_SUBREAPER, 1);

  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  std::unique_lock<std::mutex> registering(liveChildrenMutex);
  const int error = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  if (error == 0) liveChildren.insert(pid);
  registering.unlock();
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(output);
  if (error != 0) {
    outcome.output = arguments[0] + ": " + std::strerror(error);
    return outcome;
  }
  outcome.started = true;

  int status = 0;
  for (auto wait = std::chrono::milliseconds(1);; wait = std::min(wait * 2, decltype(wait)(50))) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {  // not our child any more: nothing left to wait for
      outcome.output = std::string("waiting for the child failed: ") + std::strerror(errno);
      return outcome;
    }
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > timeLimit) {
      outcome.timedOut = true;
      ::kill(-pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(wait);
  }
  outcome.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  {
    const std::lock_guard<std::mutex> lock(liveChildrenMutex);
    liveChildren.erase(pid);
  }
  // A process group's number stays taken while a member lives, so -pid is still the child's.
  outcome.leftBehind = endLeftBehind(pid);
  if (!outcome.timedOut) {
    if (WIFEXITED(status)) outcome.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  }
  outcome.output = lastBytes(outputFile, 64 * 1024);
  return outcome;
}

void limitThisChild(uint64_t maxFileBytes) {
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  const rlimit files{maxFileBytes, maxFileBytes};
  ::setrlimit(RLIMIT_FSIZE, &files);
}

std::string currentExecutable() {
  char path[4096];
  const ssize_t length = ::readlink("/proc/self/exe", path, sizeof path - 1);
  if (length <= 0) throw PathwayError("cannot find the running program (/proc/self/exe)");
  return std::string(path, static_cast<size_t>(length));
}

}  // namespace pathway
