// The integrator registry and the stage kit: names derived from the stage and the variant,
// parameters declared once by kind and checked against their declarations, and kits that mix
// variants (a student's stage on the reference's earlier stages).
#include <gtest/gtest.h>

#include "chart/chart_spec.h"
#include "core/error.h"
#include "engine/recipe_builder.h"
#include "render/integrator_registry.h"
#include "stage_under_test.h"
#include "stages/stage_catalog.h"
#include "viewer/viewer_options.h"

namespace pathway {
namespace {

// The message of the PathwayError `action` throws, or "" when it throws none.
template <typename Action>
std::string errorOf(Action action) {
  try {
    action();
  } catch (const PathwayError& error) {
    return error.what();
  }
  return "";
}

TEST(Registry, EveryStageRegistersUnderItsDeclaredNameSummaryAndParameters) {
  for (int stage = 1; stage <= kStageCount; ++stage) {
    const StageInfo& declared = stageInfo(stage);
    EXPECT_EQ(declared.number, stage);
    EXPECT_EQ(declared.name, "stage" + std::to_string(stage));
    for (Variant variant : {Variant::Student, Variant::Reference}) {
      const IntegratorInfo* info = findStageIntegrator(stage, variant);
      if (variant == Variant::Reference && !test::haveReference()) {
        EXPECT_EQ(info, nullptr);
        continue;
      }
      ASSERT_NE(info, nullptr) << declared.name << " " << variantName(variant);
      EXPECT_EQ(info->name, variant == Variant::Student ? declared.name : declared.name + "@ref");
      EXPECT_EQ(info->stage, stage);
      EXPECT_EQ(info->variant, variant);
      EXPECT_EQ(info->summary, declared.summary);
      EXPECT_EQ(info->defaultSampler, declared.defaultSampler);
      ASSERT_EQ(info->params.size(), declared.params.size());
      for (size_t i = 0; i < declared.params.size(); ++i)
        EXPECT_EQ(info->params[i].name, declared.params[i].name);
    }
    for (const OptionSpec& spec : declared.params) {
      EXPECT_TRUE(spec.accepts(spec.defaultValue)) << declared.name << " " << spec.name;
      EXPECT_FALSE(spec.help.empty()) << declared.name << " " << spec.name;
    }
  }
  EXPECT_NE(errorOf([] { stageInfo(6); }).find("no stage 6"), std::string::npos);
}

TEST(Registry, ParametersAreDeclaredByKind) {
  const StageInfo& pathTracing = stageInfo(5);
  auto find = [&](const std::string& name) -> const OptionSpec& {
    for (const OptionSpec& spec : pathTracing.params)
      if (spec.name == name) return spec;
    throw PathwayError("no " + name);
  };
  EXPECT_EQ(find("max-depth").kind, OptionKind::Integer);
  EXPECT_EQ(find("nee").kind, OptionKind::Toggle);
  EXPECT_EQ(find("light-pick").kind, OptionKind::Choice);  // a choice, not a 0/1 switch
  EXPECT_EQ(find("light-pick").options, (std::vector<std::string>{"area", "power"}));
  EXPECT_EQ(find("light-pick").format(find("light-pick").defaultValue), "power");
  EXPECT_EQ(stageInfo(2).params[1].kind, OptionKind::Real);
}

TEST(Registry, ParameterValuesAreCheckedAgainstTheirDeclarations) {
  const std::vector<OptionSpec> specs = {
      OptionSpec::integer("rays", 4, 1, 16, "rays"),
      OptionSpec::real("distance", 0.5, 0.0, 2.0, "distance"),
      OptionSpec::toggle("shadows", true, "shadows"),
      OptionSpec::choice("pick", "power", {"area", "power"}, "pick"),
  };
  const ParamValues defaults = resolveParams("x", specs, {});
  EXPECT_EQ(defaults.number("rays"), 4);
  EXPECT_EQ(defaults.number("distance"), 0.5);
  EXPECT_EQ(defaults.number("shadows"), 1.0);
  EXPECT_EQ(defaults.number("pick"), 1.0);  // the option's index: power
  EXPECT_EQ(defaults.describe(), "rays=4 distance=0.5 shadows=on pick=power");

  const ParamValues given = resolveParams(
      "x", specs, {{"rays", "16"}, {"distance", "2"}, {"shadows", "off"}, {"pick", "area"}});
  EXPECT_EQ(given.number("rays"), 16);
  EXPECT_EQ(given.number("shadows"), 0.0);
  EXPECT_EQ(given.number("pick"), 0.0);
  // What describe() writes reads back to the same values.
  std::map<std::string, std::string> text;
  for (const char* assignment : {"rays=16", "distance=2", "shadows=off", "pick=area"})
    text.insert(splitParamAssignment(assignment));
  EXPECT_EQ(resolveParams("x", specs, text), given);
  EXPECT_TRUE(resolveParams("x", specs, {{"shadows", "0"}}) ==
              resolveParams("x", specs, {{"shadows", "false"}}));

  auto refuses = [&](const std::map<std::string, std::string>& given, const std::string& needle) {
    const std::string message = errorOf([&] { resolveParams("x", specs, given); });
    return !message.empty() && message.find(needle) != std::string::npos;
  };
  EXPECT_TRUE(refuses({{"rays", "17"}}, "out of range"));
  EXPECT_TRUE(refuses({{"rays", "0"}}, "[1, 16]"));
  EXPECT_TRUE(refuses({{"rays", "2.5"}}, "whole number"));
  EXPECT_TRUE(refuses({{"rays", "many"}}, "'many'"));
  EXPECT_TRUE(refuses({{"distance", "nan"}}, "must be a number"));
  EXPECT_TRUE(refuses({{"distance", "inf"}}, "must be a number"));
  EXPECT_TRUE(refuses({{"shadows", "2"}}, "on or off"));
  EXPECT_TRUE(refuses({{"pick", "1"}}, "area or power"));
  EXPECT_TRUE(refuses({{"pick", "volume"}}, "'volume'"));
  EXPECT_TRUE(refuses({{"depth", "3"}}, "no parameter 'depth'"));
  EXPECT_EQ(splitParamAssignment("a=b").second, "b");
  EXPECT_THROW(splitParamAssignment("=b"), PathwayError);

  // Numbers set directly (the viewer's widgets) are checked the same way, never clamped.
  ParamValues values(specs);
  EXPECT_NE(errorOf([&] { values.set("x", "rays", 17); }).find("[1, 16]"), std::string::npos);
  EXPECT_NE(errorOf([&] { values.set("x", "pick", 2); }).find("area or power"), std::string::npos);
  EXPECT_NE(errorOf([&] { values.set("x", "rays", 1.5); }), "");
  EXPECT_EQ(values.number("rays"), 4);  // unchanged by the refused values
}

TEST(Registry, UnknownNamesListTheKnownOnes) {
  const std::string message = errorOf([] { findIntegrator("stage7"); });
  EXPECT_NE(message.find("unknown integrator 'stage7'"), std::string::npos) << message;
  EXPECT_NE(message.find("stage5"), std::string::npos) << message;
}

TEST(StageKit, EarlierStagesComeFromTheChosenVariantAndTheStageItselfFromItsOwn) {
  // Your stage 3 on your own stages 1-2, or on the reference's.
  const StageKit own(3, Variant::Student, EarlierStages::Own);
  EXPECT_EQ(own.stage1Variant(), Variant::Student);
  EXPECT_EQ(own.stage2Variant(), Variant::Student);
  const StageKit mixed(3, Variant::Student, EarlierStages::Reference);
  EXPECT_EQ(mixed.stage1Variant(), Variant::Reference);
  EXPECT_EQ(mixed.stage2Variant(), Variant::Reference);
  // Stage 2 graded alone: the reference's stage 1 filters it, stage 2 stays the student's.
  const StageKit second(2, Variant::Student, EarlierStages::Reference);
  EXPECT_EQ(second.stage1Variant(), Variant::Reference);
  EXPECT_EQ(second.stage2Variant(), Variant::Student);
  // Stage 1 has no earlier stage: it always splats with its own functions.
  EXPECT_EQ(StageKit(1, Variant::Student, EarlierStages::Reference).stage1Variant(),
            Variant::Student);
  // The kits hand out the functions the stage files registered.
  EXPECT_NO_THROW(own.stage1());
  EXPECT_NO_THROW(own.stage2());
  if (test::haveReference()) {
    EXPECT_NE(own.stage1().splat, mixed.stage1().splat);
    EXPECT_NE(own.stage2().ambientOcclusionSample, mixed.stage2().ambientOcclusionSample);
  } else {
    // A handout has no reference: the kit names what is missing.
    const std::string message = errorOf([&] { mixed.stage2(); });
    EXPECT_NE(message.find("reference stage 2 is not built"), std::string::npos) << message;
  }
}

// RecipeBuilder is how every render is put together: it starts from the integrator's declared
// defaults and its own sampler, and refuses a name or value at the call that gives it.
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

// Every setting's default, including those a command derives with withDefault, lies in its
// declared range (a default outside it would be refused by the very command that offers it).
TEST(Settings, EveryDefaultIsInItsDeclaredRange) {
  const OptionSpec* settings[] = {&setting::kWidth,
                                  &setting::kHeight,
                                  &setting::kSamplesPerPixel,
                                  &setting::kSamplesPerPass,
                                  &setting::kSeed,
                                  &setting::kThreads,
                                  &setting::kFilterRadius,
                                  &setting::kExposure,
                                  &setting::kTileSize,
                                  &setting::kReferenceSamplesPerPixel,
                                  &setting::kFilter,
                                  &setting::kSampler,
                                  &setting::kEarlierStages,
                                  &setting::kChartWidth,
                                  &setting::kChartMaxSpp,
                                  &setting::kChartSeeds,
                                  &setting::kReferenceFactor,
                                  &kViewerSamplesPerPixel};
  for (const OptionSpec* spec : settings)
    EXPECT_TRUE(spec->accepts(spec->defaultValue)) << spec->name;
  EXPECT_EQ(setting::kChartWidth.maxValue, setting::kWidth.maxValue);  // derived, not redeclared
  EXPECT_EQ(kViewerSamplesPerPixel.maxValue, setting::kSamplesPerPixel.maxValue);
}

}  // namespace
}  // namespace pathway
