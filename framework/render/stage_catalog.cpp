#include "render/stage_catalog.h"

#include "core/error.h"
#include "render/ray_budget.h"

namespace pathway {
namespace {

// Shared by both AO stages, so that nested and 4D AO are compared at equal D.
ParamSpec aoDistance() {
  return ParamSpec::real("ao-distance", 0.25, 1e-6, 1e6, "D: how far an AO ray looks for blockers");
}

void checkNaiveRecursionBudget(const std::string& integratorName, const ParamValues& params) {
  checkRayBudget(integratorName, static_cast<uint64_t>(params.integer("branching")),
                 static_cast<uint64_t>(params.integer("depth")),
                 static_cast<uint64_t>(params.number("max-rays")));
}

std::vector<StageDeclaration> declareStages() {
  return {
      {1,
       "stage1",
       "stage1_filtering.cpp",
       "filtered supersampling: pixel filters and the splat, eye-light shading",
       {},
       SamplerType::Independent},
      {2,
       "stage2",
       "stage2_nested_ao.cpp",
       "nested AO: per eye sample, M cosine-weighted AO rays of length D",
       {ParamSpec::integer("ao-rays", 4, 1, 1024, "M: AO rays per eye sample")
            .keepingTheExpectedImage(),
        aoDistance()},
       SamplerType::Independent},
      {3,
       "stage3",
       "stage3_ao_4d.cpp",
       "4D AO: one sample = (x, y, direction) drawn together; one eye ray + one AO ray",
       {aoDistance()},
       SamplerType::Sobol},
      {4,
       "stage4",
       "stage4_naive_recursion.cpp",
       "naive recursive tracing: N random rays at every hit, down to depth D",
       {ParamSpec::integer("branching", 3, 1, 1024, "N: rays cast at every hit")
            .keepingTheExpectedImage(),
        ParamSpec::integer("depth", 2, 0, 64,
                           "D: bounces; 0 shows emitters only, 1 adds direct light"),
        ParamSpec::integer("max-rays", 1000000, 1, 1000000000000,
                           "refuse settings that cast more rays per camera sample")
            .keepingTheExpectedImage()},
       SamplerType::Independent,
       checkNaiveRecursionBudget},
      {5,
       "stage5",
       "stage5_path_tracing.cpp",
       "path tracing: one ray per bounce, next-event estimation, Russian roulette",
       {ParamSpec::integer(
            "max-depth", 5, -1, 1000,
            "most bounces a path takes (0: emitters only, 1: direct light; -1: no limit)"),
        ParamSpec::integer("rr-depth", 3, 0, 1000, "bounces before Russian roulette starts")
            .keepingTheExpectedImage(),
        ParamSpec::toggle("nee", true,
                          "next-event estimation: shadow rays to the emitters (off: only "
                          "bounces find light)")
            .keepingTheExpectedImage(),
        ParamSpec::choice("light-pick", "power", {"area", "power"},
                          "how next-event estimation picks an emitter: by area or by power")
            .keepingTheExpectedImage()},
       // Owen-scrambled Sobol': at equal time about half the relMSE of independent samples on the
       // Cornell box (docs/benchmarks.md), and unbiased (tests/stage_analytic_test.cpp).
       SamplerType::Sobol},
  };
}

}  // namespace

const StageDeclaration& stageDeclaration(int stage) {
  static const std::vector<StageDeclaration> stages = declareStages();
  if (stage < 1 || stage > kStageCount)
    throw PathwayError("there is no stage " + std::to_string(stage) + " (stages are 1 to " +
                       std::to_string(kStageCount) + ")");
  return stages[stage - 1];
}

}  // namespace pathway
