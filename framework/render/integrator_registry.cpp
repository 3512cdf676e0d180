#include "render/integrator_registry.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "render/reference_library.h"
#include "render/stage_catalog.h"
#include "render/student_stages.h"

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

namespace {

constexpr const char* kWavefrontSuffix = "@fast";

IntegratorInfo stageInfo(int stage, Variant variant, std::string name, IntegratorFactory factory) {
  const StageDeclaration& declaration = stageDeclaration(stage);
  IntegratorInfo info;
  info.name = std::move(name);
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
  return info;
}

}  // namespace

bool registerStageIntegrator(int stage, Variant variant, IntegratorFactory factory) {
  return registerIntegrator(
      stageInfo(stage, variant, stageIntegratorName(stage, variant), std::move(factory)));
}

bool registerWavefrontStageIntegrator(int stage, IntegratorFactory factory) {
  IntegratorInfo info =
      stageInfo(stage, Variant::Reference, "stage" + std::to_string(stage) + kWavefrontSuffix,
                std::move(factory));
  info.wavefront = true;
  info.summary += " (wavefront: 16-ray packets, the reference's estimator)";
  return registerIntegrator(std::move(info));
}

std::string referenceIntegratorName(int stage, ReferenceTracing tracing) {
  const std::string fast = "stage" + std::to_string(stage) + kWavefrontSuffix;
  if (tracing == ReferenceTracing::Fastest && registry().count(fast)) return fast;
  return stageIntegratorName(stage, Variant::Reference);
}

std::string referenceIntegratorFor(const std::string& name, ReferenceTracing tracing) {
  auto it = registry().find(name);
  if (it == registry().end() || it->second.stage == 0 || it->second.wavefront ||
      it->second.variant != Variant::Reference)
    return name;
  return referenceIntegratorName(it->second.stage, tracing);
}

const IntegratorInfo& findIntegrator(std::string_view requested) {
  const std::string name(requested);
  auto it = registry().find(name);
  if (it != registry().end()) return it->second;
  std::string known;
  for (const IntegratorInfo* info : allIntegrators())
    known += (known.empty() ? "" : ", ") + info->name;
  const std::string& why = referenceStagesProblem();
  auto endsWith = [&name](const std::string& suffix) {
    return name.size() > suffix.size() &&
           name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  const bool reference = endsWith("@ref") || endsWith(kWavefrontSuffix);
  // A student stage that is not here: say why (it did not compile, it changed since).
  std::string studentWhy;
  for (int stage = 1; stage <= kStageCount && studentWhy.empty(); ++stage)
    if (name == stageIntegratorName(stage, Variant::Student))
      studentWhy = studentStageProblem(stage);
  if (!studentWhy.empty()) throw PathwayError("your " + name + " is not here: " + studentWhy);
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
    if (a->stage != b->stage) return a->stage < b->stage;
    if (a->variant != b->variant) return a->variant < b->variant;
    return a->wavefront < b->wavefront;
  });
  return list;
}

}  // namespace pathway
