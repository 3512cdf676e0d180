// One number as printf's `pattern` writes it ("%.3g", "%.2f s", "%+.1f%%"): the helper the panel,
// the reports, the charts and the likely causes format their numbers with.
#pragma once

#include <cstdio>
#include <string>

namespace pathway {

inline std::string formatNumber(const char* pattern, double value) {
  char text[64];
  std::snprintf(text, sizeof text, pattern, value);
  return text;
}

}  // namespace pathway
