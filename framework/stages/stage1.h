// Stage 1 — filtered supersampling: four pixel filters and the splat.
// Your code: assignments/stage1/stage1_filtering.cpp (handout: assignments/stage1/README.md).
//
// Stage 1 has no parameters of its own: the filter and its radius are render settings
// (--filter, --filter-radius), because every later stage is filtered by your stage 1 too.
#pragma once

#include "render/stage_definition.h"

namespace pathway {

struct Stage1Params {};

inline const StageDefinition<Stage1Params>& stage1() {
  static const StageDefinition<Stage1Params> definition{
      1,
      "stage1_filtering.cpp",
      "filtered supersampling: pixel filters and the splat, eye-light shading",
      SamplerType::Independent,
      {}};
  return definition;
}

}  // namespace pathway
