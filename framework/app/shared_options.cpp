#include "app/shared_options.h"

namespace pathway {

void addSharedOptions(CLI::App& command, RenderChoices& choices) {
  command.add_option("scene", choices.scene, "glTF 2.0 scene (.gltf or .glb)")
      ->capture_default_str();
  command
      .add_option("-i,--integrator", choices.integrator,
                  "Integrator by name: stageN is yours, stageN@ref the reference")
      ->capture_default_str();
  command.add_option("-p,--param", choices.params,
                     "Integrator parameter name=value (repeatable; see pathway render --list)");
  addChoiceOption(command, setting::kEarlierStages, choices.earlierStages);
  addChoiceOption(command, setting::kSampler, choices.sampler,
                  "the integrator's; stage 3 uses sobol");
  addOption(command, setting::kSeed, choices.seed);
  addChoiceOption(command, setting::kFilter, choices.filter);
  addOption(command, setting::kFilterRadius, choices.filterRadius);
  addOption(command, setting::kLightScale, choices.lightScale);
  command.add_flag("--strict", choices.strictScene,
                   "Refuse a scene that requires KHR_lights_punctual (Blender's lamps) instead of "
                   "loading it without its lamps and a warning");
}

}  // namespace pathway
