// The subcommands of the `pathway` program. Each adds itself to the CLI11 app and runs when chosen.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace pathway {

struct Command {
  CLI::App* app;             // the parsed subcommand
  std::function<int()> run;  // runs it; returns the exit status; throws PathwayError on bad input
};

// The command line's words after "--" (for pathway cluster, which passes them on).
std::vector<std::string>& passedOnArguments();
// The words of a command that reads its own command line (the sandbox's launcher): all of them
// after the program's path, its name first. CLI11 parses only the name.
std::vector<std::string>& unparsedArguments();

Command addRenderCommand(CLI::App& app);
Command addGradeCommand(CLI::App& app);
Command addSandboxedRunCommand(CLI::App& app);  // hidden: the grader's sandboxed compiler
Command addChartCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addClusterCommand(CLI::App& app);
Command addReferenceCommand(CLI::App& app);
Command addWarptestCommand(CLI::App& app);
Command addViewCommand(CLI::App& app);  // only when built with the viewer (PATHWAY_HAS_VIEWER)

}  // namespace pathway
