#include "render/integrator_registry.h"

#include <algorithm>
#include <map>

#include "core/error.h"

namespace pathway {
namespace {

std::map<std::string, IntegratorInfo>& registry() {
  static std::map<std::string, IntegratorInfo> integrators;  // built before main() runs
  return integrators;
}

}  // namespace

std::string variantIntegratorName(const std::string& baseName, Variant variant) {
  return variant == Variant::Reference ? baseName + "@ref" : baseName;
}

bool registerIntegrator(IntegratorInfo info) {
  const std::string name = info.name;
  registry()[name] = std::move(info);
  return true;
}

const IntegratorInfo& findIntegrator(const std::string& name) {
  auto it = registry().find(name);
  if (it != registry().end()) return it->second;
  std::string known;
  for (const IntegratorInfo* info : allIntegrators())
    known += (known.empty() ? "" : ", ") + info->name;
  throw PathwayError("unknown integrator '" + name + "' (known: " + known +
                     "; 'pathway render --list' describes them)");
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
