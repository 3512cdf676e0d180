// The options `pathway render` and `pathway view` share, declared once so that their names,
// help texts, defaults and ranges cannot drift apart. Settings come from their declarations in
// render/render_settings.h and the integrators' parameters from the registry.
#pragma once

#include <CLI/CLI.hpp>
#include <limits>
#include <string>

#include "render/render_choices.h"
#include "render/render_settings.h"

namespace pathway {

void addSharedOptions(CLI::App& command, RenderChoices& choices);

// Adds --<name> for a declared setting: its help, its range and its default.
template <typename T>
CLI::Option* addSettingOption(CLI::App& command, const SettingSpec<T>& spec, T& value) {
  value = spec.defaultValue;
  CLI::Option* option = command.add_option(std::string("--") + spec.name, value, spec.help);
  // A range as wide as the type says nothing (the seed): leave it out of --help.
  if (spec.minValue != std::numeric_limits<T>::lowest() ||
      spec.maxValue != std::numeric_limits<T>::max())
    option->check(CLI::Range(spec.minValue, spec.maxValue));
  return option->capture_default_str();
}

}  // namespace pathway
