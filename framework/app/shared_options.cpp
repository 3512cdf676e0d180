#include "app/shared_options.h"

#include "film/pixel_filter.h"

namespace pathway {

void addSharedOptions(CLI::App& command, const SharedOptions& options) {
  command.add_option("scene", options.scene, "glTF 2.0 scene (.gltf or .glb)")
      ->capture_default_str();
  command
      .add_option("-i,--integrator", options.integrator,
                  "Integrator by name: stageN is yours, stageN@ref the reference")
      ->capture_default_str();
  command.add_option("-p,--param", options.params,
                     "Integrator parameter name=value (repeatable; see pathway render --list)");
  command.add_option(
      "--sampler", options.sampler,
      "independent, stratified or sobol (default: the integrator's; stage 3 uses sobol)");
  command.add_option("--seed", options.seed, "Random seed; same seed, same image")
      ->capture_default_str();
  command.add_option("--filter", options.filter, "Pixel filter: box, tent, mitchell, gaussian")
      ->capture_default_str();
  command
      .add_option("--filter-radius", options.filterRadius,
                  "Filter support in pixels (default: box 0.5, tent 1, mitchell 2, gaussian 1.5)")
      ->check(CLI::Range(0.0f, kMaxFilterRadius));
}

}  // namespace pathway
