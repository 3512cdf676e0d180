// How a stage declares itself (framework/stages/stageN.h): its number, file, summary and usual
// sampler, and a parameter table whose rows each fill one field of the stage's own typed struct.
// StageInfo is the same without the typed struct, for the registry, the CLI, the viewer and
// the grader (stages/stage_catalog.h lists the five): a stage is defined once, the rest of the
// program reads its info.
// A stage reads `setup.params.aoDistance`, so a misspelt parameter fails to compile; the CLI, the
// viewer's panel and the metadata see the same rows as options (render/parameters.h).
#pragma once

#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "render/parameters.h"
#include "render/stage_kit.h"
#include "sampling/sampler.h"
#include "scene/scene.h"

namespace pathway {

struct StageInfo {
  int number = 0;
  std::string name;  // "stage3"; the reference registers as "stage3@ref"
  std::string file;  // the stage's file, the same name in assignments/stageN and solutions/stageN
  std::string summary;
  std::vector<OptionSpec> params;
  SamplerType defaultSampler = SamplerType::Independent;
  // Refuses parameter values that must not start rendering (throws PathwayError); may be null.
  std::function<void(const std::string& integratorName, const ParamValues& params)> check;
};

// What a stage's integrator is built from: its parameters, typed, the earlier stages' functions
// and the scene. It lives while the constructor runs: copy what the integrator keeps.
template <typename Params>
struct StageSetup {
  const Params& params;
  const StageKit& kit;
  const Scene& scene;
};

// One row of a stage's parameter table: the option users set and the field it fills.
template <typename Params>
struct StageParam {
  OptionSpec option;
  std::function<void(Params&, double)> fill;
};

// `field` of Params, filled from the option's value: a whole number, a real, on/off (bool) or a
// choice (an enum whose values follow the option's list).
template <typename Params, typename Field>
StageParam<Params> stageParam(Field Params::*field, OptionSpec option) {
  return {std::move(option), [field](Params& params, double value) {
            if constexpr (std::is_same_v<Field, bool>)
              params.*field = value != 0.0;
            else if constexpr (std::is_enum_v<Field> || std::is_integral_v<Field>)
              params.*field = static_cast<Field>(static_cast<long long>(value));
            else
              params.*field = static_cast<Field>(value);
          }};
}

template <typename Params>
struct StageDefinition {
  int number = 0;
  std::string file;  // the same name in assignments/stageN and solutions/stageN
  std::string summary;
  SamplerType defaultSampler = SamplerType::Independent;
  std::vector<StageParam<Params>> params;
  // Refuses values that must not start rendering (throws PathwayError naming the integrator).
  void (*check)(const std::string& integratorName, const Params& params) = nullptr;

  Params read(const ParamValues& values) const {
    Params typed{};
    for (const StageParam<Params>& row : params) row.fill(typed, values.number(row.option.name));
    return typed;
  }

  // The same, without the typed struct: what the catalog, the CLI and the viewer read.
  StageInfo info() const {
    StageInfo declared;
    declared.number = number;
    declared.name = "stage" + std::to_string(number);
    declared.file = file;
    declared.summary = summary;
    declared.defaultSampler = defaultSampler;
    for (const StageParam<Params>& row : params) declared.params.push_back(row.option);
    if (check)
      declared.check = [definition = *this](const std::string& name, const ParamValues& values) {
        definition.check(name, definition.read(values));
      };
    return declared;
  }
};

}  // namespace pathway
