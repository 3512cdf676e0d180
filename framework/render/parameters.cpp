#include "render/parameters.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/error.h"

namespace pathway {
namespace {

const char* const kSwitchOn[] = {"on", "1", "true", "yes"};
const char* const kSwitchOff[] = {"off", "0", "false", "no"};

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

ParamSpec ParamSpec::integer(std::string name, long long defaultValue, long long minValue,
                             long long maxValue, std::string help) {
  return {std::move(name),
          ParamKind::Integer,
          static_cast<double>(defaultValue),
          static_cast<double>(minValue),
          static_cast<double>(maxValue),
          {},
          std::move(help)};
}

ParamSpec ParamSpec::real(std::string name, double defaultValue, double minValue, double maxValue,
                          std::string help) {
  return {std::move(name), ParamKind::Real, defaultValue, minValue, maxValue, {}, std::move(help)};
}

ParamSpec ParamSpec::keepingTheExpectedImage() const {
  ParamSpec spec = *this;
  spec.changesExpectedImage = false;
  return spec;
}

ParamSpec ParamSpec::toggle(std::string name, bool defaultValue, std::string help) {
  return {std::move(name), ParamKind::Switch, defaultValue ? 1.0 : 0.0, 0.0, 1.0, {},
          std::move(help)};
}

ParamSpec ParamSpec::choice(std::string name, const std::string& defaultOption,
                            std::vector<std::string> options, std::string help) {
  const auto it = std::find(options.begin(), options.end(), defaultOption);
  const double index = static_cast<double>(it - options.begin());
  const double last = static_cast<double>(options.size()) - 1.0;
  return {std::move(name),    ParamKind::Choice, index, 0.0, last,
          std::move(options), std::move(help)};
}

bool ParamSpec::accepts(double value) const {
  if (!std::isfinite(value) || value < minValue || value > maxValue) return false;
  return !isWholeNumber() || value == std::floor(value);
}

std::string ParamSpec::format(double value) const {
  switch (kind) {
    case ParamKind::Switch:
      return value != 0.0 ? "on" : "off";
    case ParamKind::Choice: {
      const auto index = static_cast<size_t>(value);
      return index < options.size() ? options[index] : "?";
    }
    case ParamKind::Integer:
      return std::to_string(static_cast<long long>(value));
    case ParamKind::Real:
      break;
  }
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string ParamSpec::describeRange() const {
  switch (kind) {
    case ParamKind::Switch:
      return "on or off";
    case ParamKind::Choice:
      return joinOptions(options);
    case ParamKind::Integer:
    case ParamKind::Real:
      break;
  }
  return "[" + format(minValue) + ", " + format(maxValue) + "]";
}

ParamValues::ParamValues(std::vector<ParamSpec> specs) : specs_(std::move(specs)) {
  for (const ParamSpec& spec : specs_) values_[spec.name] = spec.defaultValue;
}

const ParamSpec& ParamValues::spec(const std::string& owner, const std::string& name) const {
  for (const ParamSpec& candidate : specs_)
    if (candidate.name == name) return candidate;
  std::string known;
  for (const ParamSpec& candidate : specs_) known += (known.empty() ? "" : ", ") + candidate.name;
  throw PathwayError("integrator '" + owner + "' has no parameter '" + name + "'" +
                     (known.empty() ? " (it takes none)" : " (it takes: " + known + ")"));
}

void ParamValues::set(const std::string& owner, const std::string& name, double value) {
  const ParamSpec& declared = spec(owner, name);
  if (!declared.accepts(value))
    throw PathwayError("parameter '" + name + "' of '" + owner + "' is out of range: " +
                       declared.format(value) + " is not in " + declared.describeRange());
  values_[name] = value;
}

void ParamValues::setText(const std::string& owner, const std::string& name,
                          const std::string& text) {
  const ParamSpec& declared = spec(owner, name);
  const std::string prefix = "parameter '" + name + "' of '" + owner + "' ";
  switch (declared.kind) {
    case ParamKind::Switch:
      if (isOneOf(text, kSwitchOn)) return set(owner, name, 1.0);
      if (isOneOf(text, kSwitchOff)) return set(owner, name, 0.0);
      throw PathwayError(prefix + "is a switch: write on or off, got '" + text + "'");
    case ParamKind::Choice: {
      const auto it = std::find(declared.options.begin(), declared.options.end(), text);
      if (it != declared.options.end())
        return set(owner, name, static_cast<double>(it - declared.options.begin()));
      throw PathwayError(prefix + "must be " + declared.describeRange() + ", got '" + text + "'");
    }
    case ParamKind::Integer:
    case ParamKind::Real:
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

const std::string& ParamValues::choice(const std::string& name) const {
  const double index = number(name);
  for (const ParamSpec& declared : specs_)
    if (declared.name == name && declared.kind == ParamKind::Choice)
      return declared.options.at(static_cast<size_t>(index));
  throw PathwayError("internal: parameter '" + name + "' is not a choice");
}

std::string ParamValues::describe() const {
  std::string text;
  for (const ParamSpec& declared : specs_)
    text +=
        (text.empty() ? "" : " ") + declared.name + "=" + declared.format(number(declared.name));
  return text;
}

ParamValues resolveParams(const std::string& owner, const std::vector<ParamSpec>& specs,
                          const std::map<std::string, std::string>& given) {
  ParamValues values(specs);
  for (const auto& [name, text] : given) values.setText(owner, name, text);
  return values;
}

std::string expectedImageDifference(const ParamValues& a, const ParamValues& b) {
  for (const ParamSpec& spec : a.specs()) {
    if (!spec.changesExpectedImage) continue;
    for (const ParamSpec& other : b.specs()) {
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

}  // namespace pathway
