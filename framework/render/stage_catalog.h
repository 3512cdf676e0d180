// The five stages of the course as the framework knows them: name, one-line summary, parameters
// (declared once here, so the skeleton in assignments/ and the solution in solutions/ cannot
// drift apart), the sampler each stage is meant to be seen with, and any check that must refuse a
// request before rendering starts (stage 4's ray budget). `pathway render --list`, the viewer
// panel and the docs read these declarations.
#pragma once

#include <string>
#include <vector>

#include "render/parameters.h"
#include "sampling/sampler.h"

namespace pathway {

constexpr int kStageCount = 5;

struct StageDeclaration {
  int number = 0;
  std::string name;  // "stage3"; the reference registers as "stage3@ref"
  std::string file;  // the stage's file, the same name in assignments/stageN and solutions/stageN
  std::string summary;
  std::vector<ParamSpec> params;
  SamplerType defaultSampler = SamplerType::Independent;
  // Refuses parameter values that must not start rendering (throws PathwayError); may be null.
  void (*check)(const std::string& integratorName, const ParamValues& params) = nullptr;
};

// Stage `stage` in 1..kStageCount; throws PathwayError otherwise.
const StageDeclaration& stageDeclaration(int stage);

}  // namespace pathway
