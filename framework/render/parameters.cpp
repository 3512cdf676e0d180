#include "render/parameters.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace pathway {

double ParamValues::number(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end())
    throw PathwayError("internal: parameter '" + name + "' was not declared");
  return it->second;
}

std::string formatParamValue(const ParamSpec& spec, double value) {
  std::ostringstream out;
  if (spec.isInteger)
    out << static_cast<long long>(value);
  else
    out << value;
  return out.str();
}

ParamValues resolveParams(const std::string& integratorName, const std::vector<ParamSpec>& specs,
                          const std::map<std::string, std::string>& given) {
  ParamValues values;
  for (const ParamSpec& spec : specs) values.set(spec.name, spec.defaultValue);
  for (const auto& [name, text] : given) {
    const ParamSpec* spec = nullptr;
    for (const ParamSpec& candidate : specs)
      if (candidate.name == name) spec = &candidate;
    if (!spec) {
      std::string known;
      for (const ParamSpec& candidate : specs)
        known += (known.empty() ? "" : ", ") + candidate.name;
      throw PathwayError("integrator '" + integratorName + "' has no parameter '" + name + "'" +
                         (known.empty() ? " (it takes none)" : " (it takes: " + known + ")"));
    }
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    const std::string range = "[" + formatParamValue(*spec, spec->minValue) + ", " +
                              formatParamValue(*spec, spec->maxValue) + "]";
    if (text.empty() || *end != '\0' || !std::isfinite(value))
      throw PathwayError("parameter '" + name + "' of '" + integratorName +
                         "' must be a number in " + range + ", got '" + text + "'");
    if (spec->isInteger && value != std::floor(value))
      throw PathwayError("parameter '" + name + "' of '" + integratorName +
                         "' must be a whole number in " + range + ", got '" + text + "'");
    if (value < spec->minValue || value > spec->maxValue)
      throw PathwayError("parameter '" + name + "' of '" + integratorName +
                         "' is out of range: " + text + " is not in " + range);
    values.set(name, value);
  }
  return values;
}

std::pair<std::string, std::string> splitParamAssignment(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw PathwayError("parameter '" + text + "' must be written name=value");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

}  // namespace pathway
