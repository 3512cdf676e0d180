// `pathway grade --make-references [--stage N]...`: the references of the selected cases, rendered
// from solutions/ into --references (instructors), with a progress line per case on a terminal.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>

#include "app/grade_modes.h"
#include "grade/grading_reference.h"
#include "scene/gltf_loader.h"

namespace pathway {

int makeReferencesMode(const GradeOptions& options) {
  std::filesystem::create_directories(options.references);
  std::map<std::string, std::unique_ptr<Scene>> scenes;
  for (const GradingCase* c : selectedCases(options)) {
    const auto start = std::chrono::steady_clock::now();
    auto& scene = scenes[c->scene];
    if (!scene) scene = std::make_unique<Scene>(loadScene(kScenesDir + "/" + c->scene));
    const RayTracer tracer(*scene);
    const bool terminal = !options.quiet && ::isatty(STDERR_FILENO);
    const GradingReference reference =
        makeGradingReference(*c, tracer, options.referenceTracing(), [&](int done) {
          if (terminal)
            std::fprintf(stderr, "\r%-36s %2d/%d replicates", c->id().c_str(), done,
                         kReferenceReplicates);
        });
    const std::string path = options.references + "/" + c->referenceFile();
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    writeGradingReference(path, reference);
    if (!options.quiet)
      std::fprintf(stderr, "%s%-36s %5.1f s -> %s\n", terminal ? "\r" : "", c->id().c_str(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   path.c_str());
  }
  return 0;
}

}  // namespace pathway
