#include "engine/render_choices.h"

namespace pathway {

RecipeBuilder RenderChoices::builder() const {
  RecipeBuilder builder(integrator);
  for (const std::string& assignment : params) {
    const auto [name, value] = splitParamAssignment(assignment);
    builder.param(name, value);
  }
  builder.earlierStages(parseEarlierStages(earlierStages));
  if (!sampler.empty()) builder.sampler(parseSamplerType(sampler));
  builder.seed(seed).filter(parseFilterType(filter), filterRadius);
  return builder;
}

SceneLoadOptions RenderChoices::sceneOptions() const {
  setting::kLightScale.require(lightScale);
  return {strictScene, lightScale};
}

RenderRecipe RenderChoices::recipe() const {
  return builder();
}

}  // namespace pathway
