// Stage 2 — ambient occlusion as two nested integrals: per eye sample, M AO rays.
// Your code: assignments/stage2/stage2_nested_ao.cpp (handout: assignments/stage2/README.md).
//
// | parameter   | kind    | default | range          | your field            |
// |-------------|---------|---------|----------------|-----------------------|
// | ao-rays     | integer | 4       | [1, 1024]      | params.aoRays (M)     |
// | ao-distance | real    | 0.25    | [1e-06, 1e+06] | params.aoDistance (D) |
//
// Set them with `pathway render -i stage2 -p ao-rays=8 -p ao-distance=0.5` or in the viewer's
// panel. M changes only noise and cost; D changes the image AO converges to.
#pragma once

#include "render/stage_definition.h"

namespace pathway {

struct Stage2Params {
  int aoRays;        // M: AO rays per eye sample
  float aoDistance;  // D: how far an AO ray looks for blockers
};

// Shared with stage 3, so that nested and 4D AO are compared at equal D.
inline OptionSpec aoDistanceOption() {
  return OptionSpec::real("ao-distance", 0.25, 1e-6, 1e6, "D: how far an AO ray looks for blockers")
      .withRole(OptionRole::AoReach);
}

inline const StageDefinition<Stage2Params>& stage2() {
  static const StageDefinition<Stage2Params> definition{
      2,
      "stage2_nested_ao.cpp",
      "nested AO: per eye sample, M cosine-weighted AO rays of length D",
      SamplerType::Independent,
      {stageParam(&Stage2Params::aoRays,
                  OptionSpec::integer("ao-rays", 4, 1, 1024, "M: AO rays per eye sample")
                      .keepingTheExpectedImage()),
       stageParam(&Stage2Params::aoDistance, aoDistanceOption())}};
  return definition;
}

}  // namespace pathway
