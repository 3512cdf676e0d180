#include "render/render_choices.h"

#include <map>

namespace pathway {

RenderRecipe RenderChoices::recipe() const {
  RenderRecipe recipe;
  const IntegratorInfo& info = findIntegrator(integrator);
  recipe.integrator = info.name;
  std::map<std::string, std::string> given;
  for (const std::string& assignment : params) {
    const auto [name, value] = splitParamAssignment(assignment);
    given[name] = value;
  }
  recipe.params = resolveParams(info.name, info.params, given);
  recipe.earlierStages = parseEarlierStages(earlierStages);
  RenderSettings& s = recipe.settings;
  s.sampler = sampler.empty() ? info.defaultSampler : parseSamplerType(sampler);
  s.seed = seed;
  s.filter = parseFilterType(filter);
  s.filterRadius = filterRadius;
  return recipe;  // the settings are checked once, by the Renderer
}

}  // namespace pathway
