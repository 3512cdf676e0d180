// `pathway grade --make-references [--stage N]...`: the references of the selected cases, rendered
// from solutions/ into --references (instructors), a line per case as it is written.
#include <tbb/parallel_for.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>

#include "app/grade_modes.h"
#include "grade/grading_reference.h"
#include "scene/gltf_loader.h"

namespace pathway {

int makeReferencesMode(const GradeOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto secondsSince = [](Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };
  const auto start = Clock::now();
  std::filesystem::create_directories(options.references);
  const std::vector<const GradingCase*> cases = selectedCases(options);
  // Each scene loaded and its BVH built once, before the cases run; the cases share them.
  struct LoadedScene {
    std::unique_ptr<Scene> scene;
    std::unique_ptr<RayTracer> tracer;
  };
  std::map<std::string, LoadedScene> scenes;
  for (const GradingCase* c : cases) {
    LoadedScene& loaded = scenes[c->scene];
    if (loaded.scene) continue;
    loaded.scene = std::make_unique<Scene>(loadScene(kScenesDir + "/" + c->scene));
    loaded.tracer = std::make_unique<RayTracer>(*loaded.scene);
  }

  // The cases side by side: a small image leaves cores idle within one render, and a case's
  // reference is the same whichever thread renders it. Lines come in the order cases finish.
  std::mutex output;
  tbb::parallel_for(size_t(0), cases.size(), [&](size_t i) {
    const auto caseStart = Clock::now();
    const GradingCase& c = *cases[i];
    const GradingReference reference =
        makeGradingReference(c, *scenes.at(c.scene).tracer, options.referenceTracing());
    const std::string path = options.references + "/" + c.referenceFile();
    std::filesystem::create_directories(std::filesystem::path(path).parent_path());
    writeGradingReference(path, reference);
    const std::lock_guard<std::mutex> lock(output);
    if (!options.quiet)
      std::fprintf(stderr, "%-36s %5.1f s -> %s\n", c.id().c_str(), secondsSince(caseStart),
                   path.c_str());
  });
  if (!options.quiet)
    std::fprintf(stderr, "%zu references in %.1f s (cases rendered side by side)\n", cases.size(),
                 secondsSince(start));
  return 0;
}

}  // namespace pathway
