// The warp test of stage 5's light sampling (sampleLight): the points it places on the emitters
// against the density it claims for them (LightSample::pdfArea). Each emitter is cut into k²
// congruent small triangles of equal area; a routine whose points have the density it claims puts
// N · pdfArea · (area / k²) of N points into each, up to chance (Pearson's χ² test). Two parts
// are told apart, because students get them wrong separately: how often each emitter is chosen
// (against pdfArea · area, the pick's probability the density implies), and where on its
// triangle the point lands (uniform, for one density per triangle).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "render/emitter_picker.h"

namespace pathway {

using LightSampler = std::function<LightSample(const EmitterPicker&, float uPick, Vec2 uPoint)>;

struct LightSamplingTestSettings {
  int samples = 200000;
  int cellsPerSide = 8;  // k: k² small triangles per emitter
  uint64_t seed = 1;
  // Each of the two parts fails at p below half of this (so a correct routine fails about once in
  // 10000 seeds, as the hemisphere test does).
  double significance = 1e-4;
};

struct LightSamplingTestResult {
  int emitters = 0;
  std::vector<double> pickObserved, pickExpected;    // per emitter
  std::vector<double> pointObserved, pointExpected;  // per emitter and small triangle
  // Σ over the emitters of pdfArea · area: the probabilities of choosing them that the claimed
  // density implies; 1 for a density.
  double probabilitySum = 0.0;
  long invalid = 0;       // points not on the triangle they name (or naming none, or NaN)
  long notFinite = 0;     // points whose pdfArea is infinite or NaN
  long inconsistent = 0;  // points whose pdfArea differs from their triangle's first one
  double pickChiSquared = 0.0, pointChiSquared = 0.0;
  int pickDegrees = 0, pointDegrees = 0;
  double pickP = 1.0, pointP = 1.0;
  // The mean barycentric weight of each triangle's first corner p0: 1/3 for uniform points.
  double meanWeightOfP0 = 0.0;
  bool passed = false;
  std::string verdict;
};

// Draws settings.samples points through `sampler` with `picker` (a scene's emitters, with the
// weighting under test) and tests them against the density they claim.
LightSamplingTestResult testLightSampling(const LightSampler& sampler, const EmitterPicker& picker,
                                          const std::vector<EmissiveTriangle>& emitters,
                                          const LightSamplingTestSettings& settings);

}  // namespace pathway
