// The integrator registry: names, declarations, and parameter checking.
#include <gtest/gtest.h>

#include "core/error.h"
#include "render/integrator_registry.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

TEST(Registry, EveryStageHasAStudentVersionAndTheReferenceDeclaresTheSameParameters) {
  for (int stage = 1; stage <= 5; ++stage) {
    const std::string name = "stage" + std::to_string(stage);
    const IntegratorInfo& student = findIntegrator(name);
    EXPECT_EQ(student.stage, stage);
    EXPECT_EQ(student.variant, Variant::Student);
#ifdef PATHWAY_HAS_SOLUTIONS
    // Skeleton and solution are two copies of one file: their declarations must not drift.
    const IntegratorInfo& reference = findIntegrator(name + "@ref");
    EXPECT_EQ(reference.variant, Variant::Reference);
    EXPECT_EQ(reference.summary, student.summary);
    EXPECT_EQ(reference.defaultSampler, student.defaultSampler);
    ASSERT_EQ(reference.params.size(), student.params.size()) << name;
    for (size_t i = 0; i < student.params.size(); ++i) {
      const ParamSpec &a = student.params[i], &b = reference.params[i];
      EXPECT_EQ(a.name, b.name);
      EXPECT_EQ(a.defaultValue, b.defaultValue);
      EXPECT_EQ(a.minValue, b.minValue);
      EXPECT_EQ(a.maxValue, b.maxValue);
      EXPECT_EQ(a.isInteger, b.isInteger);
      EXPECT_EQ(a.help, b.help);
    }
#endif
    for (const ParamSpec& spec : student.params) {
      EXPECT_LE(spec.minValue, spec.defaultValue) << name << " " << spec.name;
      EXPECT_LE(spec.defaultValue, spec.maxValue) << name << " " << spec.name;
      EXPECT_FALSE(spec.help.empty()) << name << " " << spec.name;
    }
  }
}

TEST(Registry, ParametersAreCheckedAgainstTheirDeclarations) {
  const std::vector<ParamSpec> specs = {{"rays", 4, 1, 16, true, "rays"},
                                        {"distance", 0.5, 0.0, 2.0, false, "distance"}};
  const ParamValues defaults = resolveParams("x", specs, {});
  EXPECT_EQ(defaults.integer("rays"), 4);
  EXPECT_EQ(defaults.number("distance"), 0.5);
  const ParamValues given = resolveParams("x", specs, {{"rays", "16"}, {"distance", "2"}});
  EXPECT_EQ(given.integer("rays"), 16);
  auto refuses = [&](const std::map<std::string, std::string>& given, const std::string& needle) {
    try {
      resolveParams("x", specs, given);
    } catch (const PathwayError& error) {
      return std::string(error.what()).find(needle) != std::string::npos;
    }
    return false;
  };
  EXPECT_TRUE(refuses({{"rays", "17"}}, "out of range"));
  EXPECT_TRUE(refuses({{"rays", "0"}}, "[1, 16]"));
  EXPECT_TRUE(refuses({{"rays", "2.5"}}, "whole number"));
  EXPECT_TRUE(refuses({{"rays", "many"}}, "'many'"));
  EXPECT_TRUE(refuses({{"distance", "nan"}}, "must be a number"));
  EXPECT_TRUE(refuses({{"distance", "inf"}}, "must be a number"));
  EXPECT_TRUE(refuses({{"depth", "3"}}, "no parameter 'depth'"));
  EXPECT_EQ(splitParamAssignment("a=b").second, "b");
  EXPECT_THROW(splitParamAssignment("=b"), PathwayError);
}

TEST(Registry, UnknownNamesListTheKnownOnes) {
  try {
    findIntegrator("stage7");
    FAIL();
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find("stage5"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace pathway
