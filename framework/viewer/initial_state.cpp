#include "viewer/initial_state.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "render/integrator_registry.h"

namespace pathway {
namespace {

// Puts a checked recipe's integrator, parameters and earlier stages into pane `lane`.
void applyRecipe(ViewerState& state, int lane, const RenderRecipe& recipe) {
  const IntegratorInfo& info = findIntegrator(recipe.integrator);
  for (const OptionSpec& spec : info.params)
    setParamValue(state, lane, info, spec, recipe.params.number(spec.name));
  state.integrator[lane] = info.name;
  state.earlierStages[lane] = recipe.earlierStages;
}

}  // namespace

ViewerState initialState(const ViewerOptions& options) {
  ViewerState state;
  // The same checks as `pathway render`: unknown names and refused values stop here.
  const RenderRecipe left = options.choices.recipe();
  applyRecipe(state, 0, left);
  state.integrator[1] = state.integrator[0];
  state.earlierStages[1] = state.earlierStages[0];
  if (!options.splitIntegrator.empty()) {
    RenderChoices right = options.choices;
    right.integrator = options.splitIntegrator;
    right.params = options.splitParams;
    applyRecipe(state, 1, right.recipe());
    state.split = true;
    if (!options.splitSampler.empty())  // the names setting::kSampler declares
      state.splitSampler = parseSamplerType(options.splitSampler);
    if (!options.splitFilter.empty()) state.splitFilter = parseFilterType(options.splitFilter);
  }
  if (options.balance == "time")
    state.balance = Balance::EqualTime;
  else if (options.balance == "rays")
    state.balance = Balance::EqualRays;
  else
    throw PathwayError("unknown balance '" + options.balance + "' (time or rays)");
  state.settings.sampler = left.settings.sampler;
  state.settings.seed = left.settings.seed;
  state.settings.filter = left.settings.filter;
  state.settings.filterRadius = left.settings.filterRadius;
  state.settings.samplesPerPixel = options.spp;
  state.settings.samplesPerPass = options.samplesPerPass;
  state.settings.check();
  state.exposure = options.exposure;
  if (options.display == "color" || options.display == "colour")
    state.display = DisplayMode::Color;
  else if (options.display == "variance")
    state.display = DisplayMode::Variance;
  else if (options.display == "rays")
    state.display = DisplayMode::RayHeatmap;
  else
    throw PathwayError("unknown display '" + options.display + "' (color, variance or rays)");
  state.referenceSpp = options.referenceSpp;
  state.scaleTop = options.scaleTop;
  state.cacheReferences = options.cacheReferences;
  state.showHelp = options.showHelp;
  state.sceneOptions = options.choices.sceneOptions();
  state.fixedWidth = options.width;
  state.fixedHeight = options.height;
  return state;
}

void completeRenderSize(ViewerState& state, const Scene& scene) {
  if ((state.fixedWidth > 0) == (state.fixedHeight > 0)) return;
  const float aspect =
      scene.camera && scene.camera->aspectRatio ? *scene.camera->aspectRatio : 16.0f / 9.0f;
  if (state.fixedHeight == 0)
    state.fixedHeight = std::max(1, static_cast<int>(std::lround(state.fixedWidth / aspect)));
  else
    state.fixedWidth = std::max(1, static_cast<int>(std::lround(state.fixedHeight * aspect)));
}

}  // namespace pathway
