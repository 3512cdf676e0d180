// RecipeBuilder is how every render is put together: it starts from the integrator's declared
// defaults and its own sampler, and refuses a name or value at the call that gives it.
#include "render/recipe_builder.h"

#include <gtest/gtest.h>

#include "core/error.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

std::string errorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const PathwayError& error) {
    return error.what();
  }
  return "";
}

TEST(RecipeBuilder, StartsFromTheIntegratorsDeclarationsAndChecksWhatItIsGiven) {
  const RenderRecipe defaults = RecipeBuilder(test::stage(5));
  EXPECT_EQ(defaults.integrator, test::stage(5));
  EXPECT_EQ(defaults.settings.sampler, SamplerType::Sobol);  // stage 5's own
  EXPECT_EQ(defaults.params.describe(), "max-depth=5 rr-depth=3 nee=on light-pick=power");

  const RenderRecipe given = RecipeBuilder(test::stage(5))
                                 .param("nee", "off")
                                 .param("max-depth", 2.0)
                                 .size(40, 30)
                                 .spp(64, 4)
                                 .seed(9)
                                 .filter(FilterType::Tent, 1.5f)
                                 .earlierStages(EarlierStages::Reference);
  EXPECT_EQ(given.params.describe(), "max-depth=2 rr-depth=3 nee=off light-pick=power");
  EXPECT_EQ(given.settings.width, 40);
  EXPECT_EQ(given.settings.height, 30);
  EXPECT_EQ(given.settings.samplesPerPixel, 64u);
  EXPECT_EQ(given.settings.samplesPerPass, 4u);
  EXPECT_EQ(given.settings.seed, 9u);
  EXPECT_EQ(given.settings.filter, FilterType::Tent);
  EXPECT_EQ(given.settings.filterRadius, 1.5f);
  EXPECT_EQ(given.earlierStages, EarlierStages::Reference);
  // One pass unless told otherwise; another variant's values carry over.
  EXPECT_EQ(RenderRecipe(RecipeBuilder(test::stage(5)).spp(8)).settings.samplesPerPass, 8u);
  EXPECT_EQ(RenderRecipe(RecipeBuilder(test::stage(5)).params(given.params)).params, given.params);

  EXPECT_NE(errorOf([] { RecipeBuilder("stage9"); }).find("unknown integrator 'stage9'"),
            std::string::npos);
  EXPECT_NE(errorOf([] {
              RecipeBuilder(test::stage(5)).param("depth", "3");
            }).find("no parameter 'depth'"),
            std::string::npos);
  EXPECT_NE(
      errorOf([] { RecipeBuilder(test::stage(5)).param("rr-depth", "-1"); }).find("[0, 1000]"),
      std::string::npos);
}

}  // namespace
}  // namespace pathway
