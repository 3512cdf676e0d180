#include "engine/recipe_builder.h"

namespace pathway {

RecipeBuilder::RecipeBuilder(const std::string& integrator)
    : RecipeBuilder(findIntegrator(integrator)) {}

RecipeBuilder::RecipeBuilder(const IntegratorInfo& integrator) : info_(integrator) {
  recipe_.integrator = info_.name;
  recipe_.params = ParamValues(info_.params);
  recipe_.settings.sampler = info_.defaultSampler;
}

RecipeBuilder& RecipeBuilder::param(const std::string& name, const std::string& text) {
  recipe_.params.setText(info_.name, name, text);
  return *this;
}

RecipeBuilder& RecipeBuilder::param(const std::string& name, double value) {
  recipe_.params.set(info_.name, name, value);
  return *this;
}

RecipeBuilder& RecipeBuilder::params(const std::map<std::string, std::string>& given) {
  for (const auto& [name, text] : given) param(name, text);
  return *this;
}

RecipeBuilder& RecipeBuilder::params(const ParamValues& values) {
  for (const OptionSpec& spec : values.specs()) param(spec.name, values.number(spec.name));
  return *this;
}

RecipeBuilder& RecipeBuilder::earlierStages(EarlierStages earlier) {
  recipe_.earlierStages = earlier;
  return *this;
}

RecipeBuilder& RecipeBuilder::settings(const RenderSettings& settings) {
  recipe_.settings = settings;
  return *this;
}

RecipeBuilder& RecipeBuilder::size(int width, int height) {
  recipe_.settings.width = width;
  recipe_.settings.height = height;
  return *this;
}

RecipeBuilder& RecipeBuilder::spp(uint32_t spp, uint32_t perPass) {
  recipe_.settings.samplesPerPixel = spp;
  recipe_.settings.samplesPerPass = perPass > 0 ? perPass : spp;
  return *this;
}

RecipeBuilder& RecipeBuilder::sampler(SamplerType sampler) {
  recipe_.settings.sampler = sampler;
  return *this;
}

RecipeBuilder& RecipeBuilder::seed(uint64_t seed) {
  recipe_.settings.seed = seed;
  return *this;
}

RecipeBuilder& RecipeBuilder::filter(FilterType filter, float radius) {
  recipe_.settings.filter = filter;
  recipe_.settings.filterRadius = radius;
  return *this;
}

RecipeBuilder& RecipeBuilder::threads(int threads) {
  recipe_.settings.threads = threads;
  return *this;
}

}  // namespace pathway
