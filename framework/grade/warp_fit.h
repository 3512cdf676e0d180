// A goodness-of-fit test of a hemisphere sampling routine against the density it claims, as in
// Nori's warptest: draw many directions, count them in cells of (cos θ, φ), and compare the counts
// with what the claimed pdf integrates to over each cell (Pearson's χ² test). A student sees a
// wrong warp or a wrong pdf here, before any image.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "core/math.h"

namespace pathway {

// The routine under test: directions in the local frame (z along the normal) from two numbers
// in [0, 1)², and the density per unit solid angle the routine claims for a direction of a given
// cos θ (stage 2's sampleCosineHemisphere and cosineHemispherePdf).
struct HemisphereWarp {
  std::function<Vec3(Vec2)> sample;
  std::function<float(float cosTheta)> pdf;
};

struct WarpTestSettings {
  int samples = 200000;
  int cosThetaCells = 16;  // cells of equal width in cos θ (equal solid angle per cell)
  int phiCells = 32;
  uint64_t seed = 1;
  // The test fails at p below this. 10⁻⁴: a correct routine fails about once in 10000 seeds (the
  // course allows one false alarm in 1000); every wrong routine of the mutant sets fails at each of
  // 1000 seeds (docs/warptest.md).
  double significance = 1e-4;
  // Directions kept for a picture (the first ones drawn): enough to see a pattern, few enough to
  // draw.
  int keptDirections = 3000;
};

// Counts and expectations per cell, row-major: cell (i, j) holds cos θ in [i, i+1)/cosThetaCells
// and φ in [j, j+1)·2π/phiCells.
struct WarpTestResult {
  int cosThetaCells = 0, phiCells = 0;
  std::vector<double> observed, expected;
  double pdfIntegral = 0.0;  // ∫ pdf dω over the hemisphere: 1 for a density
  long invalid = 0;          // directions not of unit length, below the horizon, or NaN
  double chiSquared = 0.0;
  int degreesOfFreedom = 0;  // cells after pooling those expected to hold fewer than 5, minus 1
  double p = 1.0;
  // Mean cos θ of the directions drawn and the mean the pdf claims: which way they are off.
  double observedMeanCosTheta = 0.0, expectedMeanCosTheta = 0.0;
  bool passed = false;
  std::string verdict;           // one line: what passed, or what is wrong and which way
  std::vector<Vec3> directions;  // the first settings.keptDirections valid ones
};

// Pearson's statistic Σ (O − E)² / E over the cells, the cells whose expectation is below 5
// pooled into one (added to the last cell kept when they expect under 5 together); returns the
// statistic and sets `degrees` to the cells kept minus 1.
double pooledChiSquared(const std::vector<double>& observed, const std::vector<double>& expected,
                        int& degrees);

WarpTestResult testHemisphereWarp(const HemisphereWarp& warp, const WarpTestSettings& settings);

}  // namespace pathway
