// `pathway reference`: where this program's reference stages (stageN@ref) come from, and whether
// a compiled reference library can be loaded here (stage_loading/reference_library.h).
#include <cstdio>
#include <string>

#include "app/commands.h"
#include "stage_loading/reference_library.h"

namespace pathway {
namespace {

struct ReferenceOptions {
  std::string check;  // a library to check
};

int run(const ReferenceOptions& options) {
  if (!options.check.empty()) {
    const std::string problem = referenceLibraryProblem(options.check);
    std::printf("%s\n", problem.empty() ? (options.check + ": can be loaded here").c_str()
                                        : problem.c_str());
    return problem.empty() ? 0 : 1;
  }
  const ReferenceStages& stages = loadReferenceStages();
  std::printf("reference stages: %s\nthis program: %s, stage interface %s\n",
              stages.describe().c_str(), buildPlatform(), stageInterface());
  return stages.source == ReferenceStages::Source::None ? 1 : 0;
}

}  // namespace

Command addReferenceCommand(CLI::App& app) {
  auto options = std::make_shared<ReferenceOptions>();
  CLI::App* reference = app.add_subcommand(
      "reference", "Say where the reference stages (stageN@ref) come from, or check a library");
  reference->footer(
      "Examples:\n"
      "  pathway reference                 built in, loaded from a library, or why not available\n"
      "  pathway reference --check reference/stage3.so\n"
      "A handout's reference stages come compiled in reference/stage1.so ... stage5.so; the\n"
      "environment variable PATHWAY_REFERENCE_LIBRARIES names another folder to load instead.");
  reference->add_option("--check", options->check,
                        "Check that this reference library can be loaded by this program");
  return {reference, [options] { return run(*options); }};
}

}  // namespace pathway
