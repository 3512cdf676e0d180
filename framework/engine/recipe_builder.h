// The one way a RenderRecipe is put together: the integrator by name, with its declared
// parameters at their defaults and the sampler it is meant to be seen with, then whatever
// differs. Names and parameter values are checked as they are given (PathwayError naming the
// first refused); the settings' ranges are checked where they enter and when the render starts.
//   RenderRecipe recipe = RecipeBuilder("stage5@ref").param("nee", "off").size(64, 48).spp(16);
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "engine/render_session.h"

namespace pathway {

class RecipeBuilder {
 public:
  explicit RecipeBuilder(const std::string& integrator);  // throws for an unknown name
  explicit RecipeBuilder(const IntegratorInfo& integrator);

  // A parameter as a user writes it ("4", "on", "power"), or as a widget holds it (a number).
  RecipeBuilder& param(const std::string& name, const std::string& text);
  RecipeBuilder& param(const std::string& name, double value);
  RecipeBuilder& params(const std::map<std::string, std::string>& given);
  // Values of the same declarations (e.g. the other variant of the same stage).
  RecipeBuilder& params(const ParamValues& values);
  RecipeBuilder& earlierStages(EarlierStages earlier);
  // Every setting at once (the viewer's panel holds them together); the calls below change one.
  RecipeBuilder& settings(const RenderSettings& settings);
  RecipeBuilder& size(int width, int height);
  // `spp` samples per pixel, in passes of `perPass` (0: all in one pass). Without this call the
  // settings' defaults hold (16 spp, one per pass).
  RecipeBuilder& spp(uint32_t spp, uint32_t perPass = 0);
  RecipeBuilder& sampler(SamplerType sampler);
  RecipeBuilder& seed(uint64_t seed);
  RecipeBuilder& filter(FilterType filter, float radius = 0.0f);
  RecipeBuilder& threads(int threads);

  const RenderRecipe& recipe() const { return recipe_; }
  operator RenderRecipe() const {
    return recipe_;
  }  // NOLINT: a builder reads as its result (a copy)

 private:
  const IntegratorInfo& info_;
  RenderRecipe recipe_;
};

}  // namespace pathway
