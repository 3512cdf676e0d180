// Integrator parameters, declared once (name, default, range, help) by the stage that owns them.
// The CLI, the viewer panel and the docs all read the same declarations.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace pathway {

struct ParamSpec {
  std::string name;  // lower-case, dash-separated: "ao-distance"
  double defaultValue = 0.0;
  double minValue = 0.0;
  double maxValue = 0.0;
  bool isInteger = false;  // integers and on/off switches (0 or 1)
  std::string help;
};

class ParamValues {
 public:
  double number(const std::string& name) const;  // throws if the name was never declared
  int integer(const std::string& name) const { return static_cast<int>(number(name)); }
  bool flag(const std::string& name) const { return number(name) != 0.0; }
  void set(const std::string& name, double value) { values_[name] = value; }

 private:
  std::map<std::string, double> values_;
};

// Starts from the defaults and applies `given` (name -> text). Unknown names, text that is not a
// number, non-integers for integer parameters and values out of range throw PathwayError naming
// the integrator, the parameter and the allowed range.
ParamValues resolveParams(const std::string& integratorName, const std::vector<ParamSpec>& specs,
                          const std::map<std::string, std::string>& given);

// "name=value" -> (name, value); throws PathwayError on text without '='.
std::pair<std::string, std::string> splitParamAssignment(const std::string& text);

std::string formatParamValue(const ParamSpec& spec, double value);

}  // namespace pathway
