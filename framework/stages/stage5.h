// Stage 5 — path tracing: one ray per bounce, next-event estimation, Russian roulette.
// Your code: assignments/stage5/stage5_path_tracing.cpp (handout: assignments/stage5/README.md).
//
// | parameter  | kind    | default | range         | your field                 |
// |------------|---------|---------|---------------|----------------------------|
// | max-depth  | integer | 5       | [-1, 1000]    | params.maxDepth            |
// | rr-depth   | integer | 3       | [0, 1000]     | params.rouletteDepth       |
// | nee        | toggle  | on      | on or off     | params.nextEventEstimation |
// | light-pick | choice  | power   | area or power | params.lightPick           |
//
// max-depth changes the image the path tracer converges to (-1: no limit); the others change
// only its noise and cost. The stage renders with the Sobol' sampler unless --sampler says
// otherwise: at equal time about half the relMSE of independent samples on the Cornell box
// (docs/benchmarks.md), and unbiased (tests/stage_analytic_test.cpp).
#pragma once

#include "render/emitter_picker.h"
#include "render/stage_definition.h"

namespace pathway {

struct Stage5Params {
  int maxDepth;                // most bounces a path takes (-1: no limit)
  int rouletteDepth;           // bounces before Russian roulette starts
  bool nextEventEstimation;    // shadow rays to the emitters at every hit
  EmitterWeighting lightPick;  // how NEE picks an emitter
};

inline const StageDefinition<Stage5Params>& stage5() {
  static const StageDefinition<Stage5Params> definition{
      5,
      "stage5_path_tracing.cpp",
      "path tracing: one ray per bounce, next-event estimation, Russian roulette",
      SamplerType::Sobol,
      {stageParam(&Stage5Params::maxDepth,
                  OptionSpec::integer("max-depth", 5, -1, 1000,
                                      "most bounces a path takes (0: emitters only, 1: direct "
                                      "light; -1: no limit)")
                      .withRole(OptionRole::RecursionDepth)),
       stageParam(
           &Stage5Params::rouletteDepth,
           OptionSpec::integer("rr-depth", 3, 0, 1000, "bounces before Russian roulette starts")
               .keepingTheExpectedImage()),
       stageParam(&Stage5Params::nextEventEstimation,
                  OptionSpec::toggle("nee", true,
                                     "next-event estimation: shadow rays to the emitters (off: "
                                     "only bounces find light)")
                      .keepingTheExpectedImage()
                      .withRole(OptionRole::NextEventEstimation)),
       // The options in the order of EmitterWeighting's values.
       stageParam(&Stage5Params::lightPick,
                  OptionSpec::choice("light-pick", "power", {"area", "power"},
                                     "how next-event estimation picks an emitter: by area or by "
                                     "power")
                      .keepingTheExpectedImage())}};
  return definition;
}

}  // namespace pathway
