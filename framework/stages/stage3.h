// Stage 3 — ambient occlusion as one 4D integral: (x, y, ω) drawn together, one AO ray.
// Your code: assignments/stage3/stage3_ao_4d.cpp (handout: assignments/stage3/README.md).
//
// | parameter   | kind | default | range          | your field            |
// |-------------|------|---------|----------------|-----------------------|
// | ao-distance | real | 0.25    | [1e-06, 1e+06] | params.aoDistance (D) |
//
// D is declared once for stages 2 and 3 (stages/stage2.h), so both estimate the same image.
// Stage 3 renders with the Sobol' sampler unless --sampler says otherwise: its pixel position
// and AO direction are one stratified 4D point.
#pragma once

#include "stages/stage2.h"

namespace pathway {

struct Stage3Params {
  float aoDistance;  // D: how far an AO ray looks for blockers
};

inline const StageDefinition<Stage3Params>& stage3() {
  static const StageDefinition<Stage3Params> definition{
      3,
      "stage3_ao_4d.cpp",
      "4D AO: one sample = (x, y, direction) drawn together; one eye ray + one AO ray",
      SamplerType::Sobol,
      {stageParam(&Stage3Params::aoDistance, aoDistanceOption())}};
  return definition;
}

}  // namespace pathway
