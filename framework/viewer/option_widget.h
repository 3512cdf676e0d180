// The viewer's widget for a declared option (render/parameters.h), made from its declaration:
// a checkbox for a toggle, a combo for a choice, a slider for a number (on a log scale where the
// range spans decades), with its help, default and range as the tooltip. Every widget keeps its
// value inside the declared range (AlwaysClamp also holds for values typed with Ctrl+click), so a
// render never sees a value it would refuse.
#pragma once

#include <type_traits>

#include "render/parameters.h"

namespace pathway {

// `format` overrides the number's printf format ("%+.1f stops"). Returns true when the user
// changed the value.
bool optionWidget(const char* label, const OptionSpec& spec, double& value,
                  const char* format = nullptr);

// The same for a setting of another type: a number, or an enum a choice stands for.
template <typename T>
bool optionWidget(const char* label, const OptionSpec& spec, T& value,
                  const char* format = nullptr) {
  double number;
  if constexpr (std::is_enum_v<T>)
    number = static_cast<double>(static_cast<int>(value));
  else
    number = static_cast<double>(value);
  if (!optionWidget(label, spec, number, format)) return false;
  if constexpr (std::is_enum_v<T>)
    value = static_cast<T>(static_cast<int>(number));
  else
    value = static_cast<T>(number);
  return true;
}

}  // namespace pathway
