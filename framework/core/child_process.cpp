#include "core/child_process.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "core/error.h"
#include "core/number_format.h"

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

// The bytes the files below `folder` take (their sizes, or the blocks they hold where more: a
// sparse file counts as written), and how many entries there are; a missing folder holds none.
// A folder that cannot be read through (a child made part of it unreadable) counts as full.
struct FolderUse {
  uint64_t bytes = 0;
  size_t entries = 0;
  bool unreadable = false;
};
FolderUse folderUse(const std::string& folder) {
  FolderUse use;
  std::error_code error;
  std::filesystem::recursive_directory_iterator it(folder, error), end;
  if (error) return use;  // not there (yet)
  for (; it != end; it.increment(error)) {
    if (error) break;
    ++use.entries;
    struct stat info {};
    if (::lstat(it->path().c_str(), &info) == 0)
      use.bytes += std::max<uint64_t>(static_cast<uint64_t>(info.st_size),
                                      static_cast<uint64_t>(info.st_blocks) * 512u);
  }
  use.unreadable = static_cast<bool>(error);
  return use;
}

// A descriptor moved to 10 or above (close-on-exec), so that the child's 0-3 can be laid out
// from it in any order, whatever this process had open. Closes the original.
int movedUp(int fd) {
  if (fd < 0) return fd;  // errno says why it was not opened
  const int moved = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
  const int why = errno;
  ::close(fd);
  errno = why;
  return moved;
}

// More entries than any case writes (an image and a log): past it, a child is filling the folder
// with empty files (the disk's inodes), whatever their bytes.
constexpr size_t kWatchedFolderEntries = 1000;

}  // namespace

std::vector<std::string> untrustedChildEnvironment() {
  std::vector<std::string> environment = {"PATH=/usr/local/bin:/usr/bin:/bin", "HOME=/nonexistent",
                                          "LANG=C.UTF-8"};
#if defined(__SANITIZE_ADDRESS__)
  // The sanitizers read their options from the environment: the build's, not a secret.
  for (const char* name : {"ASAN_OPTIONS", "UBSAN_OPTIONS", "LSAN_OPTIONS"})
    if (const char* value = std::getenv(name))
      environment.push_back(std::string(name) + "=" + value);
#endif
  return environment;
}

ChildOptions untrustedChildOptions(bool confined) {
  ChildOptions options;
  if (confined)
    options.environment = untrustedChildEnvironment();
  else
    options.keepDescriptors = true;
  return options;
}

std::string ChildOutcome::describe(double timeLimit) const {
  if (!started) return "could not be started";
  if (overQuota)
    return "wrote more than " + bytesText(quotaBytes) +
           " of files (the grader's limit on what one run may write) and was stopped";
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
                      const std::string& outputFile, const ChildOptions& options) {
  ChildOutcome outcome;
  int report[2] = {-1, -1};
  if (options.reportChannel) {
    if (::pipe2(report, O_CLOEXEC) != 0)
      throw PathwayError(std::string("cannot make a pipe for a child: ") + std::strerror(errno));
    report[0] = movedUp(report[0]);
    report[1] = movedUp(report[1]);
  }
  const int output = movedUp(
      ::open(outputFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NOFOLLOW, 0644));
  if (output < 0) {
    const std::string why = std::strerror(errno);
    for (int fd : report)
      if (fd >= 0) ::close(fd);
    throw PathwayError(outputFile + ": cannot write: " + why);
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, output, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, output, STDERR_FILENO);
  if (!options.keepDescriptors)
    posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  if (options.reportChannel)
    posix_spawn_file_actions_adddup2(&actions, report[1], kChildReportDescriptor);
  // Nothing else this process has open, whatever its close-on-exec flag.
  if (!options.keepDescriptors)
    posix_spawn_file_actions_addclosefrom_np(
        &actions, (options.reportChannel ? kChildReportDescriptor : STDERR_FILENO) + 1);
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
  std::vector<char*> written;
  if (options.environment) {
    for (const std::string& entry : *options.environment)
      written.push_back(const_cast<char*>(entry.c_str()));
    written.push_back(nullptr);
  }
  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  std::unique_lock<std::mutex> registering(liveChildrenMutex);
  const int error = posix_spawnp(&pid, argv[0], &actions, &attributes, argv.data(),
                                 options.environment ? written.data() : environ);
  if (error == 0) liveChildren.insert(pid);
  registering.unlock();
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(output);
  if (report[1] >= 0) ::close(report[1]);
  // What the child says on its report channel: read as it comes (a pipe holds 64 KiB; past
  // 4 KiB the rest is read and dropped, so a child that keeps writing never blocks on it).
  std::string reported;
  const auto readReport = [&] {
    char buffer[4096];
    for (ssize_t n; report[0] >= 0 && (n = ::read(report[0], buffer, sizeof buffer)) > 0;) {
      const size_t room = reported.size() < sizeof buffer ? sizeof buffer - reported.size() : 0;
      reported.append(buffer, std::min(static_cast<size_t>(n), room));
    }
  };
  if (report[0] >= 0) ::fcntl(report[0], F_SETFL, O_NONBLOCK);
  struct ReportCloser {
    int fd;
    ~ReportCloser() {
      if (fd >= 0) ::close(fd);
    }
  } closer{report[0]};
  if (error != 0) {
    outcome.output = arguments[0] + ": " + std::strerror(error);
    return outcome;
  }
  outcome.started = true;

  // Whether the watched folder holds more than its quota: checked while the child runs, and once
  // more when it has ended (what it wrote as it exited counts too).
  const auto overQuota = [&] {
    if (options.folderQuotaBytes == 0 || outcome.overQuota) return outcome.overQuota;
    const FolderUse use = folderUse(options.watchedFolder);
    outcome.overQuota = use.unreadable || use.bytes > options.folderQuotaBytes ||
                        use.entries > kWatchedFolderEntries;
    outcome.quotaBytes = options.folderQuotaBytes;
    return outcome.overQuota;
  };
  int status = 0;
  for (auto wait = std::chrono::milliseconds(1);; wait = std::min(wait * 2, decltype(wait)(50))) {
    readReport();
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
    if (overQuota()) {
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
  overQuota();
  if (!outcome.timedOut && !outcome.overQuota) {
    if (WIFEXITED(status)) outcome.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) outcome.signal = WTERMSIG(status);
  }
  outcome.output = lastBytes(outputFile, 64 * 1024);
  readReport();
  outcome.report = reported;
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
