#include "render/parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace pathway {
namespace {

const char* const kToggleOn[] = {"on", "1", "true", "yes"};
const char* const kToggleOff[] = {"off", "0", "false", "no"};

bool isOneOf(const std::string& text, const char* const (&words)[4]) {
  return std::find(std::begin(words), std::end(words), text) != std::end(words);
}

std::string joinOptions(const std::vector<std::string>& options) {
  std::string text;
  for (size_t i = 0; i < options.size(); ++i)
    text += (i == 0 ? "" : i + 1 == options.size() ? " or " : ", ") + options[i];
  return text;
}

}  // namespace

const char* optionKindName(OptionKind kind) {
  static const char* const names[] = {"integer", "real", "toggle", "choice"};
  return names[static_cast<int>(kind)];
}

OptionSpec OptionSpec::integer(std::string name, long long defaultValue, double minValue,
                               double maxValue, std::string help) {
  return {std::move(name),
          OptionKind::Integer,
          static_cast<double>(defaultValue),
          minValue,
          maxValue,
          {},
          std::move(help)};
}

OptionSpec OptionSpec::real(std::string name, double defaultValue, double minValue, double maxValue,
                            std::string help) {
  return {std::move(name), OptionKind::Real, defaultValue, minValue, maxValue, {}, std::move(help)};
}

OptionSpec OptionSpec::withDefault(double value, std::string newHelp) const {
  OptionSpec spec = *this;
  spec.defaultValue = value;
  spec.help = std::move(newHelp);
  return spec;
}

OptionSpec OptionSpec::keepingTheExpectedImage() const {
  OptionSpec spec = *this;
  spec.changesExpectedImage = false;
  return spec;
}

OptionSpec OptionSpec::withRole(OptionRole role) const {
  OptionSpec spec = *this;
  spec.role = role;
  return spec;
}

const OptionSpec* optionWithRole(const std::vector<OptionSpec>& options, OptionRole role) {
  for (const OptionSpec& option : options)
    if (option.role == role) return &option;
  return nullptr;
}

OptionSpec OptionSpec::toggle(std::string name, bool defaultValue, std::string help) {
  return {std::move(name), OptionKind::Toggle, defaultValue ? 1.0 : 0.0, 0.0, 1.0, {},
          std::move(help)};
}

OptionSpec OptionSpec::choice(std::string name, const std::string& defaultOption,
                              std::vector<std::string> options, std::string help) {
  const auto it = std::find(options.begin(), options.end(), defaultOption);
  const double index = static_cast<double>(it - options.begin());
  const double last = static_cast<double>(options.size()) - 1.0;
  return {std::move(name),    OptionKind::Choice, index, 0.0, last,
          std::move(options), std::move(help)};
}

bool OptionSpec::accepts(double value) const {
  if (!std::isfinite(value) || value < minValue || value > maxValue) return false;
  return !isWholeNumber() || value == std::floor(value);
}

void OptionSpec::require(double value) const {
  if (!accepts(value))
    throw PathwayError(name + " must be in " + describeRange() + ", got " + format(value));
}

std::string OptionSpec::format(double value) const {
  switch (kind) {
    case OptionKind::Toggle:
      return value != 0.0 ? "on" : "off";
    case OptionKind::Choice: {
      const auto index = static_cast<size_t>(value);
      return index < options.size() ? options[index] : "?";
    }
    case OptionKind::Integer:
      if (std::fabs(value) < 9e18) return std::to_string(static_cast<long long>(value));
      break;  // beyond long long (the seed's range): as a real number
    case OptionKind::Real:
      break;
  }
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string OptionSpec::describeRange() const {
  switch (kind) {
    case OptionKind::Toggle:
      return "on or off";
    case OptionKind::Choice:
      return joinOptions(options);
    case OptionKind::Integer:
    case OptionKind::Real:
      break;
  }
  return "[" + format(minValue) + ", " + format(maxValue) + "]";
}

ParamValues::ParamValues(std::vector<OptionSpec> specs) : specs_(std::move(specs)) {
  for (const OptionSpec& spec : specs_) values_[spec.name] = spec.defaultValue;
}

const OptionSpec& ParamValues::spec(const std::string& owner, const std::string& name) const {
  for (const OptionSpec& candidate : specs_)
    if (candidate.name == name) return candidate;
  std::string known;
  for (const OptionSpec& candidate : specs_) known += (known.empty() ? "" : ", ") + candidate.name;
  throw PathwayError("integrator '" + owner + "' has no parameter '" + name + "'" +
                     (known.empty() ? " (it takes none)" : " (it takes: " + known + ")"));
}

void ParamValues::set(const std::string& owner, const std::string& name, double value) {
  const OptionSpec& declared = spec(owner, name);
  if (!declared.accepts(value))
    throw PathwayError("parameter '" + name + "' of '" + owner + "' is out of range: " +
                       declared.format(value) + " is not in " + declared.describeRange());
  values_[name] = value;
}

void ParamValues::setText(const std::string& owner, const std::string& name,
                          const std::string& text) {
  const OptionSpec& declared = spec(owner, name);
  const std::string prefix = "parameter '" + name + "' of '" + owner + "' ";
  switch (declared.kind) {
    case OptionKind::Toggle:
      if (isOneOf(text, kToggleOn)) return set(owner, name, 1.0);
      if (isOneOf(text, kToggleOff)) return set(owner, name, 0.0);
      throw PathwayError(prefix + "is a toggle: write on or off, got '" + text + "'");
    case OptionKind::Choice: {
      const auto it = std::find(declared.options.begin(), declared.options.end(), text);
      if (it != declared.options.end())
        return set(owner, name, static_cast<double>(it - declared.options.begin()));
      throw PathwayError(prefix + "must be " + declared.describeRange() + ", got '" + text + "'");
    }
    case OptionKind::Integer:
    case OptionKind::Real:
      break;
  }
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  const std::string range = declared.describeRange();
  if (text.empty() || *end != '\0' || !std::isfinite(value))
    throw PathwayError(prefix + "must be a number in " + range + ", got '" + text + "'");
  if (declared.isWholeNumber() && value != std::floor(value))
    throw PathwayError(prefix + "must be a whole number in " + range + ", got '" + text + "'");
  if (!declared.accepts(value))
    throw PathwayError(prefix + "is out of range: " + text + " is not in " + range);
  values_[name] = value;
}

double ParamValues::number(const std::string& name) const {
  auto it = values_.find(name);
  if (it == values_.end())
    throw PathwayError("internal: parameter '" + name + "' was not declared");
  return it->second;
}

std::string ParamValues::describe() const {
  std::string text;
  for (const OptionSpec& declared : specs_)
    text +=
        (text.empty() ? "" : " ") + declared.name + "=" + declared.format(number(declared.name));
  return text;
}

ParamValues resolveParams(const std::string& owner, const std::vector<OptionSpec>& specs,
                          const std::map<std::string, std::string>& given) {
  ParamValues values(specs);
  for (const auto& [name, text] : given) values.setText(owner, name, text);
  return values;
}

std::string expectedImageDifference(const ParamValues& a, const ParamValues& b) {
  for (const OptionSpec& spec : a.specs()) {
    if (!spec.changesExpectedImage) continue;
    for (const OptionSpec& other : b.specs()) {
      if (other.name != spec.name || !other.changesExpectedImage) continue;
      const double mine = a.number(spec.name), theirs = b.number(spec.name);
      if (mine != theirs)
        return spec.name + "=" + spec.format(mine) + " (not " + other.format(theirs) + ")";
    }
  }
  return "";
}

std::pair<std::string, std::string> splitParamAssignment(const std::string& text) {
  const size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw PathwayError("parameter '" + text + "' must be written name=value");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

std::map<std::string, std::string> parseParamList(const std::string& described) {
  std::map<std::string, std::string> given;
  std::istringstream words(described);
  for (std::string word; words >> word;) given.insert(splitParamAssignment(word));
  return given;
}

}  // namespace pathway
