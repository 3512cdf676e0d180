#include "grade/robust_fit.h"

#include <cmath>
#include <utility>

namespace pathway {

double huberLoss(double r) {
  const double a = std::fabs(r);
  return a <= kHuberLimit ? r * r : 2.0 * kHuberLimit * a - kHuberLimit * kHuberLimit;
}

double totalHuberLoss(const Vector& r) {
  double sum = 0.0;
  for (double value : r) sum += huberLoss(value);
  return sum;
}

namespace {

// Weighted least squares: solves (Xᵀ W X) β = Xᵀ W y. Empty when the columns are degenerate.
std::vector<double> solve(const Vector& y, const Vector& w, const std::vector<Vector>& columns) {
  const size_t k = columns.size();
  std::vector<std::vector<double>> a(k, std::vector<double>(k + 1, 0.0));  // [Gram | Xᵀy]
  for (size_t i = 0; i < k; ++i) {
    for (size_t j = 0; j < k; ++j)
      for (size_t n = 0; n < y.size(); ++n) a[i][j] += w[n] * columns[i][n] * columns[j][n];
    for (size_t n = 0; n < y.size(); ++n) a[i][k] += w[n] * columns[i][n] * y[n];
  }
  const std::vector<std::vector<double>> gram = a;
  for (size_t i = 0; i < k; ++i) {  // Gaussian elimination with partial pivoting
    size_t pivot = i;
    for (size_t r = i + 1; r < k; ++r)
      if (std::fabs(a[r][i]) > std::fabs(a[pivot][i])) pivot = r;
    std::swap(a[i], a[pivot]);
    if (!(std::fabs(a[i][i]) > 1e-12 * (1.0 + std::fabs(gram[i][i])))) return {};
    for (size_t r = 0; r < k; ++r) {
      if (r == i) continue;
      const double f = a[r][i] / a[i][i];
      for (size_t c = i; c <= k; ++c) a[r][c] -= f * a[i][c];
    }
  }
  std::vector<double> beta;
  for (size_t i = 0; i < k; ++i) beta.push_back(a[i][k] / a[i][i]);
  return beta;
}

}  // namespace

Fit robustFit(const Vector& y, const std::vector<Vector>& columns, double lossOfY) {
  constexpr int kIterations = 8;
  Vector w(y.size(), 1.0), r(y.size());
  Fit fit;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    fit.coefficients = solve(y, w, columns);
    if (fit.coefficients.empty()) return {};
    for (size_t n = 0; n < y.size(); ++n) {
      r[n] = y[n];
      for (size_t i = 0; i < columns.size(); ++i) r[n] -= fit.coefficients[i] * columns[i][n];
      w[n] = std::fabs(r[n]) <= kHuberLimit ? 1.0 : kHuberLimit / std::fabs(r[n]);
    }
  }
  fit.explained = lossOfY - totalHuberLoss(r);
  return fit;
}

}  // namespace pathway
