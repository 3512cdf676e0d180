// pathway: the course's one program. `pathway --help` lists the subcommands.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <exception>
#include <vector>

#include "app/commands.h"
#include "core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"Pathway: from pixel filtering to path tracing, one stage at a time."};
  app.require_subcommand(1);
  std::vector<pathway::Command> commands = {
      pathway::addRenderCommand(app), pathway::addGradeCommand(app), pathway::addChartCommand(app)};
#ifdef PATHWAY_HAS_VIEWER
  commands.push_back(pathway::addViewCommand(app));
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    return app.exit(error);
  }
  try {
    for (const pathway::Command& command : commands)
      if (command.app->parsed()) return command.run();
  } catch (const pathway::PathwayError& error) {
    std::fprintf(stderr, "pathway: error: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pathway: internal error: %s\n", error.what());
    return 2;
  }
  return 0;
}
