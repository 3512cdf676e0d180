// The options `pathway render` and `pathway view` share, and the helpers that make every
// command's option from its declaration (engine/render_settings.h, chart/chart_spec.h), so that
// names, help texts, defaults and ranges cannot drift apart.
#pragma once

#include <CLI/CLI.hpp>
#include <limits>
#include <string>

#include "engine/render_choices.h"
#include "engine/render_settings.h"

namespace pathway {

void addSharedOptions(CLI::App& command, RenderChoices& choices);

// Adds --<name> for a declared option (render/parameters.h): its help, its range and its
// default, which `value` takes.
template <typename T>
CLI::Option* addOption(CLI::App& command, const OptionSpec& spec, T& value) {
  value = spec.defaultAs<T>();
  CLI::Option* option = command.add_option("--" + spec.name, value, spec.help);
  // A range as wide as the type (the seed's) says nothing: left out of --help.
  if (spec.minValue > static_cast<double>(std::numeric_limits<T>::lowest()) ||
      spec.maxValue < static_cast<double>(std::numeric_limits<T>::max()))
    option->check(CLI::Range(static_cast<T>(spec.minValue), static_cast<T>(spec.maxValue)));
  return option->capture_default_str();
}

// A choice's option, written by name (the name is checked where it is read, with the choices
// listed): its default name, or none when `whenNotGiven` says how it is worked out.
inline CLI::Option* addChoiceOption(CLI::App& command, const OptionSpec& spec, std::string& value,
                                    const std::string& whenNotGiven = "") {
  const std::string help = spec.help + ": " + spec.describeRange();
  if (!whenNotGiven.empty()) {
    value.clear();
    return command.add_option("--" + spec.name, value, help + " (default: " + whenNotGiven + ")");
  }
  value = spec.format(spec.defaultValue);
  return command.add_option("--" + spec.name, value, help)->capture_default_str();
}

// The same for an option whose value, when it is not given, is worked out later (`value` stays
// 0): `render --height` from the camera's aspect ratio, `view --width` from the window.
template <typename T>
CLI::Option* addOptionWorkedOut(CLI::App& command, const OptionSpec& spec, T& value,
                                const std::string& whenNotGiven) {
  value = T{};
  return command
      .add_option("--" + spec.name, value, spec.help + " (default: " + whenNotGiven + ")")
      ->check(CLI::Range(static_cast<T>(spec.minValue), static_cast<T>(spec.maxValue)));
}

}  // namespace pathway
