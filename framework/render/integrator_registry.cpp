#include "render/integrator_registry.h"

#include <algorithm>
#include <map>

#include "core/error.h"
#include "render/registration_gate.h"

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
  if (!admitRegistration(info.stage, info.variant, info.name)) return false;
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

std::map<std::pair<int, Variant>, std::string>& missingReasons() {
  static std::map<std::pair<int, Variant>, std::string> reasons;
  return reasons;
}

// "stage3@fast": the wavefront version of reference stage 3.
std::string wavefrontIntegratorName(int stage) {
  return "stage" + std::to_string(stage) + kWavefrontSuffix;
}

// The reason noted for the stage `name` names ("stage3", "stage3@ref", "stage3@fast"), and its
// variant; "" when it names none that a loader noted.
std::string missingReasonFor(const std::string& name, Variant& variant) {
  for (const auto& [stageAndVariant, why] : missingReasons()) {
    const auto [stage, noted] = stageAndVariant;
    if (name == stageIntegratorName(stage, noted) ||
        (noted == Variant::Reference && name == wavefrontIntegratorName(stage))) {
      variant = noted;
      return why;
    }
  }
  return "";
}

IntegratorInfo integratorInfoFor(const StageInfo& stage, Variant variant, std::string name,
                                 IntegratorFactory factory) {
  IntegratorInfo info;
  info.name = std::move(name);
  info.stage = stage.number;
  info.variant = variant;
  info.summary = stage.summary;
  info.params = stage.params;
  info.defaultSampler = stage.defaultSampler;
  info.create = [name = info.name, check = stage.check,
                 factory = std::move(factory)](const IntegratorSetup& setup) {
    if (check) check(name, setup.params);
    return factory(setup);
  };
  return info;
}

}  // namespace

bool registerStageIntegrator(const StageInfo& stage, Variant variant, IntegratorFactory factory) {
  return registerIntegrator(integratorInfoFor(
      stage, variant, stageIntegratorName(stage.number, variant), std::move(factory)));
}

bool registerWavefrontStageIntegrator(const StageInfo& stage, IntegratorFactory factory) {
  IntegratorInfo info = integratorInfoFor(
      stage, Variant::Reference, wavefrontIntegratorName(stage.number), std::move(factory));
  info.wavefront = true;
  info.summary += " (wavefront: 16-ray packets, the reference's estimator)";
  return registerIntegrator(std::move(info));
}

void noteMissingStage(int stage, Variant variant, std::string why) {
  missingReasons()[{stage, variant}] = std::move(why);
}

std::string missingStageReason(int stage, Variant variant) {
  const auto found = missingReasons().find({stage, variant});
  return found == missingReasons().end() ? "" : found->second;
}

std::string referenceStageMissing(int stage) {
  const std::string why = missingStageReason(stage, Variant::Reference);
  return "the reference stage " + std::to_string(stage) + " is not available (" +
         (why.empty() ? "not built in" : why) + ")";
}

std::string referenceIntegratorName(int stage, ReferenceTracing tracing) {
  const std::string fast = wavefrontIntegratorName(stage);
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
  // A stage that is not here: say why (it did not compile, it changed since, the reference
  // library was refused).
  Variant variant = Variant::Student;
  const std::string why = missingReasonFor(name, variant);
  if (!why.empty() && variant == Variant::Student)
    throw PathwayError("your " + name + " is not here: " + why);
  throw PathwayError("unknown integrator '" + name + "' (known: " + known +
                     "; 'pathway render --list' describes them)" +
                     (why.empty() ? "" : "; no reference stages: " + why));
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
