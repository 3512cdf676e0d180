// How both programs (`pathway` and `pathway-child`) end on an error: one line that names it, and
// an exit status that says what kind (1: the user's input or the machine, 2: a bug of ours).
#pragma once

#include <cstdio>
#include <exception>

#include "core/error.h"

namespace pathway {

// Runs `body` and returns its exit status, or the error's when it throws.
template <typename Body>
int runReportingErrors(Body body) {
  try {
    return body();
  } catch (const PathwayError& error) {
    std::fprintf(stderr, "pathway: error: %s\n", error.what());
    return 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pathway: internal error: %s\n", error.what());
    return 2;
  }
}

}  // namespace pathway
