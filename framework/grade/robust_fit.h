// A robust linear fit, for the likely cause of a difference (grade/difference_diagnosis.h): the
// tile differences, each divided by its noise, fitted by a few patterns. Monte Carlo noise has
// heavy tails, so a few tiles far out must not outweigh a pattern that explains all the others:
// Huber's loss, minimised by iteratively reweighted least squares.
#pragma once

#include <vector>

namespace pathway {

using Vector = std::vector<double>;  // one value per tile and channel

// Beyond this many standard deviations a value's loss grows like a line, not a square.
inline constexpr double kHuberLimit = 3.0;

// Huber's loss, doubled so that it is r² for |r| <= kHuberLimit (noise alone gives about 1 per
// value), and its sum over a vector.
double huberLoss(double r);
double totalHuberLoss(const Vector& r);

struct Fit {
  double explained = 0.0;            // how much the fit lowers the total loss of y
  std::vector<double> coefficients;  // one per column; empty when the columns are degenerate
};

// Fits y by Σ coefficient_i · columns[i] (all already whitened); `lossOfY` is totalHuberLoss(y).
Fit robustFit(const Vector& y, const std::vector<Vector>& columns, double lossOfY);

}  // namespace pathway
