// One exception type for every user-facing failure (bad file, bad parameter, ...).
// The CLI catches it, prints "pathway: <message>" and exits non-zero; nothing else is printed.
#pragma once

#include <stdexcept>
#include <string>

namespace pathway {

class PathwayError : public std::runtime_error {
 public:
  explicit PathwayError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace pathway
