// `pathway run-sandboxed ... -- PROGRAM ARGS`: runs a program inside the grader's sandbox
// (core/sandboxed_command.h), hidden from --help. Only the grader runs it, with the command line
// SandboxedCommand::toArguments() wrote; CLI11 sees the subcommand's name only.
#include "app/commands.h"
#include "core/sandboxed_command.h"

namespace pathway {

std::vector<std::string>& unparsedArguments() {
  static std::vector<std::string> arguments;
  return arguments;
}

Command addSandboxedRunCommand(CLI::App& app) {
  CLI::App* launcher =
      app.add_subcommand(SandboxedCommand::kCommand, "Run a program in the grader's sandbox");
  launcher->group("");  // not listed
  return {launcher, []() -> int {
            runSandboxedCommand(SandboxedCommand::fromArguments(unparsedArguments()));
          }};
}

}  // namespace pathway
