#include "spawn.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

extern char** environ;

namespace pathway::bench {
namespace {

long long monotonicNs() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec;
}

}  // namespace

SpawnedRun spawnCapturingStdout(const std::vector<std::string>& arguments) {
  int pipeEnds[2];
  if (::pipe2(pipeEnds, O_CLOEXEC) != 0)
    throw PathwayError(std::string("cannot create a pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipeEnds[1], STDOUT_FILENO);
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);

  SpawnedRun run;
  run.launchNs = monotonicNs();
  std::vector<std::string> environment = {"PATHWAY_LAUNCH_NS=" + std::to_string(run.launchNs)};
  for (char** variable = environ; *variable; ++variable)
    if (std::strncmp(*variable, "PATHWAY_LAUNCH_NS=", 18) != 0) environment.push_back(*variable);
  std::vector<char*> envp;
  for (std::string& variable : environment) envp.push_back(variable.data());
  envp.push_back(nullptr);

  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  ::close(pipeEnds[1]);
  if (error != 0) {
    ::close(pipeEnds[0]);
    throw PathwayError("cannot start " + arguments[0] + ": " + std::strerror(error));
  }
  char buffer[4096];
  for (;;) {
    const ssize_t count = ::read(pipeEnds[0], buffer, sizeof buffer);
    if (count > 0) run.outcome.output.append(buffer, static_cast<size_t>(count));
    if (count == 0 || (count < 0 && errno != EINTR)) break;
  }
  ::close(pipeEnds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  run.seconds = (monotonicNs() - run.launchNs) * 1e-9;
  run.outcome.started = true;
  run.outcome.seconds = run.seconds;
  if (WIFEXITED(status)) run.outcome.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) run.outcome.signal = WTERMSIG(status);
  return run;
}

}  // namespace pathway::bench
