// Stage 4 — naive recursive tracing: N random rays at every hit, down to depth D.
// Your code: assignments/stage4/stage4_naive_recursion.cpp (handout: assignments/stage4/README.md).
//
// | parameter | kind    | default | range              | your field           |
// |-----------|---------|---------|--------------------|----------------------|
// | branching | integer | 3       | [1, 1024]          | params.branching (N) |
// | depth     | integer | 2       | [0, 64]            | params.depth (D)     |
// | max-rays  | integer | 1000000 | [1, 1000000000000] | params.maxRays       |
//
// A camera sample casts 1 + N + N² + … + N^D rays; a request above max-rays is refused before
// rendering starts (render/ray_budget.h), so a typo cannot run for hours.
#pragma once

#include <cstdint>

#include "render/ray_budget.h"
#include "render/stage_definition.h"

namespace pathway {

struct Stage4Params {
  int branching;    // N: rays cast at every hit
  int depth;        // D: bounces; 0 shows emitters only, 1 adds direct light
  int64_t maxRays;  // refuse settings that cast more rays per camera sample
};

inline void checkStage4RayBudget(const std::string& integratorName, const Stage4Params& params) {
  checkRayBudget(integratorName, static_cast<uint64_t>(params.branching),
                 static_cast<uint64_t>(params.depth), static_cast<uint64_t>(params.maxRays));
}

inline const StageDefinition<Stage4Params>& stage4() {
  static const StageDefinition<Stage4Params> definition{
      4,
      "stage4_naive_recursion.cpp",
      "naive recursive tracing: N random rays at every hit, down to depth D",
      SamplerType::Independent,
      {stageParam(&Stage4Params::branching,
                  OptionSpec::integer("branching", 3, 1, 1024, "N: rays cast at every hit")
                      .keepingTheExpectedImage()),
       stageParam(&Stage4Params::depth,
                  OptionSpec::integer("depth", 2, 0, 64,
                                      "D: bounces; 0 shows emitters only, 1 adds direct light")
                      .withRole(OptionRole::RecursionDepth)),
       stageParam(&Stage4Params::maxRays,
                  OptionSpec::integer("max-rays", 1000000, 1, 1000000000000,
                                      "refuse settings that cast more rays per camera sample")
                      .keepingTheExpectedImage())},
      checkStage4RayBudget};
  return definition;
}

}  // namespace pathway
