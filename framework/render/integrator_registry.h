// Integrators are found by name. Each stage file registers its integrator once, with its
// parameters; the student's version is "stageN", the reference (from solutions/) "stageN@ref".
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/variant.h"
#include "render/integrator.h"
#include "render/parameters.h"

namespace pathway {

struct IntegratorInfo {
  std::string name;  // "stage2" or "stage2@ref"
  int stage = 0;     // 1..5, the course stage it belongs to
  Variant variant = Variant::Student;
  std::string summary;  // one line for --list
  std::vector<ParamSpec> params;
  // Builds the integrator for a scene; may throw PathwayError for parameter combinations it
  // refuses (before any rendering starts).
  std::function<std::unique_ptr<Integrator>(const ParamValues&, const Scene&)> create;
  // The sampler this stage is meant to be seen with, when the user does not choose one.
  SamplerType defaultSampler = SamplerType::Independent;
};

// Registers at static-initialisation time; returns true so it can initialise a static bool.
bool registerIntegrator(IntegratorInfo info);

// Throws PathwayError listing the known names when `name` is unknown.
const IntegratorInfo& findIntegrator(const std::string& name);
// All integrators, sorted by stage, student before reference.
std::vector<const IntegratorInfo*> allIntegrators();

// The name a stage registers under in the variant being compiled.
std::string variantIntegratorName(const std::string& baseName, Variant variant);

}  // namespace pathway
