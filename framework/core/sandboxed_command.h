// A program run inside the sandbox (core/sandbox.h): how the grader compiles a student's stage
// file, so that the compiler, working on untrusted source, reads only the framework, that file's
// folder and the system, and writes only the build folder (a stage file's #include of another
// submission, or of a reference, fails like any missing file). The pathway program itself is the
// launcher: `pathway run-sandboxed ... -- PROGRAM ARGS` (a hidden subcommand) shuts itself in,
// then runs the program, which stays in the sandbox with everything it starts.
#pragma once

#include <string>
#include <vector>

#include "core/sandbox.h"

namespace pathway {

struct SandboxedCommand {
  static constexpr const char* kCommand = "run-sandboxed";

  SandboxMode mode = SandboxMode::Auto;
  SandboxPolicy policy;              // policy.startsPrograms: true (a compiler runs several)
  std::vector<std::string> program;  // the program and its arguments

  // The launcher's command line after the pathway program's path: kCommand, the sandbox, "--",
  // the program.
  std::vector<std::string> toArguments() const;
  // Reads what toArguments() wrote; throws PathwayError naming the first argument it cannot take.
  static SandboxedCommand fromArguments(const std::vector<std::string>& arguments);
};

// The launcher's part: enters the sandbox, points TMPDIR at the first writable folder (a
// compiler's temporary files), and replaces this process with the program. Returns only by
// throwing PathwayError (the sandbox could not be entered, or the program not started).
[[noreturn]] void runSandboxedCommand(const SandboxedCommand& command);

}  // namespace pathway
