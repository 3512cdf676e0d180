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
  std::string seal;   // a library to seal (the build's step after linking it)
};

int run(const ReferenceOptions& options) {
  if (!options.seal.empty()) {
    sealReferenceLibrary(options.seal);
    return 0;
  }
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
      "  pathway reference --check reference/libpathway_reference.so\n"
      "A handout's reference stages come compiled in reference/libpathway_reference.so; the\n"
      "environment variable PATHWAY_REFERENCE_LIBRARY names another file to load instead.");
  reference->add_option("--check", options->check,
                        "Check that this reference library can be loaded by this program");
  reference->add_option("--seal", options->seal)->group("");  // the build's step
  return {reference, [options] { return run(*options); }};
}

}  // namespace pathway
