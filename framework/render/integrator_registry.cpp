#include "render/integrator_registry.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "render/reference_library.h"
#include "render/stage_catalog.h"

namespace pathway {
namespace {

std::map<std::string, IntegratorInfo>& registry() {
  static std::map<std::string, IntegratorInfo> integrators;  // built before main() runs
  return integrators;
}

std::vector<std::string>& log() {
  static std::vector<std::string> names;
  return names;
}

}  // namespace

std::string stageIntegratorName(int stage, Variant variant) {
  const std::string name = "stage" + std::to_string(stage);
  return variant == Variant::Reference ? name + "@ref" : name;
}

bool registerIntegrator(IntegratorInfo info) {
  const std::string name = info.name;
  registry()[name] = std::move(info);
  log().push_back(name);
  return true;
}

const std::vector<std::string>& registrationLog() {
  return log();
}

bool registerStageIntegrator(int stage, Variant variant, IntegratorFactory factory) {
  const StageDeclaration& declaration = stageDeclaration(stage);
  IntegratorInfo info;
  info.name = stageIntegratorName(stage, variant);
  info.stage = stage;
  info.variant = variant;
  info.summary = declaration.summary;
  info.params = declaration.params;
  info.defaultSampler = declaration.defaultSampler;
  info.create = [name = info.name, check = declaration.check,
                 factory = std::move(factory)](const IntegratorSetup& setup) {
    if (check) check(name, setup.params);
    return factory(setup);
  };
  return registerIntegrator(std::move(info));
}

const IntegratorInfo& findIntegrator(const std::string& name) {
  auto it = registry().find(name);
  if (it != registry().end()) return it->second;
  std::string known;
  for (const IntegratorInfo* info : allIntegrators())
    known += (known.empty() ? "" : ", ") + info->name;
  const std::string& why = referenceStagesProblem();
  const bool reference = name.size() > 4 && name.compare(name.size() - 4, 4, "@ref") == 0;
  throw PathwayError("unknown integrator '" + name + "' (known: " + known +
                     "; 'pathway render --list' describes them)" +
                     (reference && !why.empty() ? "; no reference stages: " + why : ""));
}

const IntegratorInfo* findStageIntegrator(int stage, Variant variant) {
  auto it = registry().find(stageIntegratorName(stage, variant));
  return it != registry().end() ? &it->second : nullptr;
}

std::vector<const IntegratorInfo*> allIntegrators() {
  std::vector<const IntegratorInfo*> list;
  for (const auto& entry : registry()) list.push_back(&entry.second);
  std::stable_sort(list.begin(), list.end(), [](const IntegratorInfo* a, const IntegratorInfo* b) {
    return a->stage != b->stage ? a->stage < b->stage : a->variant < b->variant;
  });
  return list;
}

}  // namespace pathway
