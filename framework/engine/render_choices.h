// What a user chooses for a render before it is checked, as `pathway render` and `pathway view`
// read it from their shared options: names and text. recipe() checks it into a RenderRecipe.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/recipe_builder.h"
#include "scene/gltf_loader.h"

namespace pathway {

struct RenderChoices {
  std::string scene;
  std::string integrator = setting::kIntegrator;
  std::vector<std::string> params;  // "name=value", checked against the integrator's declarations
  std::string earlierStages = setting::kEarlierStages.format(setting::kEarlierStages.defaultValue);
  std::string sampler;  // empty: the integrator's own default
  uint64_t seed = setting::kSeed.defaultAs<uint64_t>();
  std::string filter = setting::kFilter.format(setting::kFilter.defaultValue);
  float filterRadius = setting::kFilterRadius.defaultAs<float>();  // 0: the filter's own radius
  bool strictScene = false;  // refuse a scene requiring lamps instead of ignoring them (--strict)
  float lightScale = setting::kLightScale.defaultAs<float>();

  // How the scene is to be loaded. Throws PathwayError for a light scale out of its range.
  SceneLoadOptions sceneOptions() const;

  // The recipe these choices describe: integrator, parameters, earlier stages, sampler, seed and
  // filter (the other settings keep their defaults). Throws PathwayError naming the first unknown
  // name or refused parameter value; the settings' ranges are checked when the render starts.
  RecipeBuilder builder() const;  // to set more (size, spp, ...)
  RenderRecipe recipe() const;
};

}  // namespace pathway
