// pathway: the course's one program. `pathway --help` lists the subcommands.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/reporting_errors.h"
#include "core/sandboxed_command.h"
#include "render/registration_gate.h"
#include "stage_loading/reference_library.h"
#include "stage_loading/student_stages.h"

int main(int argc, char** argv) {
  // The stages built into the program have registered; from here on only the libraries it loads
  // register, each as what it is loaded as (render/registration_gate.h).
  pathway::endBuiltInRegistrations();
  CLI::App app{"Pathway: from pixel filtering to path tracing, one stage at a time."};
  app.require_subcommand(1);
  std::vector<pathway::Command> commands = {
      pathway::addRenderCommand(app),  pathway::addGradeCommand(app),
      pathway::addChartCommand(app),   pathway::addMergeCommand(app),
      pathway::addClusterCommand(app), pathway::addWarptestCommand(app)};
  commands.push_back(pathway::addSandboxedRunCommand(app));  // hidden: its sandboxed compiler
  const pathway::Command reference = pathway::addReferenceCommand(app);
  commands.push_back(reference);
#ifdef PATHWAY_HAS_VIEWER
  commands.push_back(pathway::addViewCommand(app));
#endif
  // What follows "--" in `pathway cluster ...` is passed on as it is, to the commands its tasks
  // run. It is split off here because CLI11 2.1 refuses it after a long option with a value.
  int parsed = argc;
  for (int i = 2; argc > 1 && std::string(argv[1]) == "cluster" && i < argc; ++i)
    if (std::string(argv[i]) == "--") {
      parsed = i;
      pathway::passedOnArguments().assign(argv + i + 1, argv + argc);
      break;
    }
  // The sandbox's launcher reads its command line itself (core/sandboxed_command.h).
  if (argc > 1 && std::string(argv[1]) == pathway::SandboxedCommand::kCommand) {
    parsed = 2;
    pathway::unparsedArguments().assign(argv + 1, argv + argc);
  }
  try {
    app.parse(parsed, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  }
  // The reference stages: built in, or a handout's compiled library. Whatever is off with a
  // library is said once here; everything that needs no reference works on without it.
  const pathway::ReferenceStages& stages = pathway::loadReferenceStages();
  if (!stages.problem.empty() && !reference.app->parsed())
    std::fprintf(stderr, "pathway: note: reference stages %s\n", stages.describe().c_str());
  return pathway::runReportingErrors([&] {
    for (const pathway::Command& command : commands) {
      if (!command.app->parsed()) continue;
      // The commands that render the student's stages load them (stage_loading/student_stages.h);
      // the grader builds the stage files itself and loads them only in its sandboxed child.
      const std::string name = command.app->get_name();
      if (name == "render" || name == "view" || name == "chart") pathway::loadStudentStages();
      return command.run();
    }
    return 0;
  });
}
