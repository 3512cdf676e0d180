// Rendering and statistics helpers for the stage tests.
#pragma once

#include <cmath>
#include <functional>
#include <map>
#include <string>

#include "engine/render_session.h"

namespace pathway::test {

// Two-sided z bound for statistical checks: P(|z| > 4.5) = 6.8e-6 per check for a correct
// estimator, so the ~50 such checks in the suite give a false alarm less than once in 2900 runs
// (and never for the fixed seeds used here unless the code changes).
constexpr double kZBound = 4.5;

struct Estimate {
  double mean = 0.0;
  double standardError = 0.0;  // of `mean`, from the pixels' own variance estimates
  size_t pixels = 0;
};

struct RenderSpec {
  std::string integrator;
  std::map<std::string, std::string> params;  // as on the command line: "nee" -> "off"
  int width = 32, height = 32;
  uint32_t spp = 16;
  SamplerType sampler = SamplerType::Independent;
  uint64_t seed = 1;
  EarlierStages earlierStages = EarlierStages::Own;
};

RenderResult render(const Scene& scene, const RenderSpec& spec);

// Mean of one channel over the pixels `include` accepts (all by default). The box filter keeps
// pixels independent, so the standard error is sqrt(Σ var_pixel) / count.
Estimate meanOverPixels(const RenderResult& result, int channel = 0,
                        const std::function<bool(int, int)>& include = {});

// |a - b| within kZBound combined standard errors (plus an optional known bias allowance).
bool agree(const Estimate& a, const Estimate& b, double allowance = 0.0);
bool agree(const Estimate& a, double expected, double allowance = 0.0);

}  // namespace pathway::test
