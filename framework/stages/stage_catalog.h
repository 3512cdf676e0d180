// The five stages of the course as the framework knows them: name, one-line summary, parameters,
// the sampler each stage is meant to be seen with, and any check that must refuse a request
// before rendering starts (stage 4's ray budget). Each stage declares these beside its code
// (framework/stages/stageN.h, shared by the skeleton and the solution, so they cannot drift
// apart); this catalog holds them without the stages' typed structs, for `pathway render
// --list`, the viewer panel, the grader and the docs.
#pragma once

#include "render/stage_definition.h"

namespace pathway {

constexpr int kStageCount = 5;

// Stage `stage` in 1..kStageCount; throws PathwayError otherwise.
const StageInfo& stageInfo(int stage);

}  // namespace pathway
