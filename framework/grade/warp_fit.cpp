#include "grade/warp_fit.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/error.h"
#include "core/number_format.h"
#include "grade/statistics.h"
#include "sampling/pcg32.h"

namespace pathway {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kSmallestExpectedCount = 5.0;  // below it χ² is no longer χ²-distributed
constexpr double kPdfIntegralTolerance = 1e-3;

// ∫ f(c) dc over [a, b] by 4-point Gauss-Legendre on 64 panels: exact for a pdf that is a
// polynomial of degree 7 or less in cos θ, and (an open rule) never evaluated at the ends, where a
// right pdf may step to 0 (at the horizon, cos θ = 0).
template <typename F>
double integrate(F f, double a, double b) {
  constexpr int kPanels = 64;
  constexpr double kNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                0.8611363115940526};
  constexpr double kWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                  0.3478548451374538};
  const double h = (b - a) / kPanels;
  double sum = 0.0;
  for (int k = 0; k < kPanels; ++k) {
    const double middle = a + (k + 0.5) * h;
    for (int n = 0; n < 4; ++n) sum += kWeights[n] * f(middle + 0.5 * h * kNodes[n]);
  }
  return sum * 0.5 * h;
}

bool isUpperUnitVector(const Vec3& d) {
  if (!std::isfinite(d.x) || !std::isfinite(d.y) || !std::isfinite(d.z)) return false;
  return std::fabs(glm::length(d) - 1.0f) < 1e-3f && d.z >= 0.0f;
}

std::string describeFailure(const WarpTestResult& r, long samples) {
  std::ostringstream out;
  if (r.invalid > 0) {
    out << r.invalid << " of " << samples
        << " directions are not unit vectors in the upper hemisphere (NaN, not normalised, or "
           "below the surface)";
    return out.str();
  }
  if (std::fabs(r.pdfIntegral - 1.0) > kPdfIntegralTolerance) {
    out << "your pdf integrates to " << formatNumber("%.3g", r.pdfIntegral)
        << " over the hemisphere, not 1: it is not a density";
    return out.str();
  }
  // Which way: the mean cos θ of the directions against the pdf's, each off by chance about
  // σ/√N (σ ≤ 1/2 for a variable in [0, 1]).
  const double chance = 3.0 * 0.5 / std::sqrt(static_cast<double>(samples));
  const double shift = r.observedMeanCosTheta - r.expectedMeanCosTheta;
  if (shift > chance)
    out << "your directions crowd towards the pole";
  else if (shift < -chance)
    out << "your directions crowd towards the horizon";
  else
    out << "your directions do not follow your pdf, though they lean neither towards the pole nor "
           "the horizon: some azimuths or bands get too many";
  out << " (mean cos θ " << formatNumber("%.3g", r.observedMeanCosTheta) << ", your pdf says "
      << formatNumber("%.3g", r.expectedMeanCosTheta)
      << "): χ² = " << formatNumber("%.3g", r.chiSquared) << " on " << r.degreesOfFreedom
      << " degrees of freedom, p = " << formatNumber("%.3g", r.p);
  return out.str();
}

}  // namespace

double pooledChiSquared(const std::vector<double>& observed, const std::vector<double>& expected,
                        int& degrees) {
  if (observed.size() != expected.size() || observed.empty())
    throw PathwayError(
        "pooledChiSquared: observed and expected counts differ in size or are empty");
  std::vector<std::pair<double, double>> kept;  // (expected, observed)
  double pooledExpected = 0.0, pooledObserved = 0.0;
  for (size_t i = 0; i < observed.size(); ++i) {
    if (expected[i] >= kSmallestExpectedCount) {
      kept.emplace_back(expected[i], observed[i]);
    } else {
      pooledExpected += expected[i];
      pooledObserved += observed[i];
    }
  }
  if (pooledExpected >= kSmallestExpectedCount || (kept.empty() && pooledExpected > 0.0)) {
    kept.emplace_back(pooledExpected, pooledObserved);
  } else if (pooledExpected > 0.0 || pooledObserved > 0.0) {
    // Too little left to stand alone: join the cell that expects least.
    auto smallest = std::min_element(kept.begin(), kept.end());
    smallest->first += pooledExpected;
    smallest->second += pooledObserved;
  }
  double statistic = 0.0;
  for (const auto& [e, o] : kept) statistic += (o - e) * (o - e) / e;
  degrees = static_cast<int>(kept.size()) - 1;
  return statistic;
}

WarpTestResult testHemisphereWarp(const HemisphereWarp& warp, const WarpTestSettings& settings) {
  if (settings.samples < 1000 || settings.cosThetaCells < 1 || settings.phiCells < 1)
    throw PathwayError("warp test: at least 1000 samples and one cell in cos θ and in φ");
  WarpTestResult r;
  r.cosThetaCells = settings.cosThetaCells;
  r.phiCells = settings.phiCells;
  const size_t cells = static_cast<size_t>(r.cosThetaCells) * r.phiCells;
  r.observed.assign(cells, 0.0);
  r.expected.assign(cells, 0.0);

  // Expected counts: the pdf depends on cos θ alone, and dω = d(cos θ) dφ.
  const auto pdf = [&](double c) { return static_cast<double>(warp.pdf(static_cast<float>(c))); };
  const double phiWidth = kTwoPi / r.phiCells;
  for (int i = 0; i < r.cosThetaCells; ++i) {
    const double c0 = double(i) / r.cosThetaCells, c1 = double(i + 1) / r.cosThetaCells;
    const double perCell = settings.samples * phiWidth * integrate(pdf, c0, c1);
    for (int j = 0; j < r.phiCells; ++j) r.expected[size_t(i) * r.phiCells + j] = perCell;
  }
  r.pdfIntegral = kTwoPi * integrate(pdf, 0.0, 1.0);
  r.expectedMeanCosTheta =
      r.pdfIntegral > 0.0
          ? kTwoPi * integrate([&](double c) { return c * pdf(c); }, 0.0, 1.0) / r.pdfIntegral
          : 0.0;

  // Observed counts.
  Pcg32 random(settings.seed);
  double cosThetaSum = 0.0;
  for (int n = 0; n < settings.samples; ++n) {
    const Vec2 u(random.nextFloat(), random.nextFloat());
    const Vec3 d = warp.sample(u);
    if (!isUpperUnitVector(d)) {
      ++r.invalid;
      continue;
    }
    const double cosTheta = std::min(static_cast<double>(d.z), std::nextafter(1.0, 0.0));
    double phi = std::atan2(static_cast<double>(d.y), static_cast<double>(d.x));
    if (phi < 0.0) phi += kTwoPi;
    const int i = std::min(static_cast<int>(cosTheta * r.cosThetaCells), r.cosThetaCells - 1);
    const int j = std::min(static_cast<int>(phi / phiWidth), r.phiCells - 1);
    r.observed[size_t(i) * r.phiCells + j] += 1.0;
    cosThetaSum += cosTheta;
    if (r.directions.size() < static_cast<size_t>(settings.keptDirections))
      r.directions.push_back(d);
  }
  const long valid = settings.samples - r.invalid;
  r.observedMeanCosTheta = valid > 0 ? cosThetaSum / valid : 0.0;

  r.chiSquared = pooledChiSquared(r.observed, r.expected, r.degreesOfFreedom);
  r.p = r.degreesOfFreedom > 0 ? chiSquaredUpperTail(r.chiSquared, r.degreesOfFreedom) : 1.0;
  r.passed = r.invalid == 0 && std::fabs(r.pdfIntegral - 1.0) <= kPdfIntegralTolerance &&
             r.p >= settings.significance;
  if (r.passed) {
    std::ostringstream out;
    out << "passed: χ² = " << formatNumber("%.3g", r.chiSquared) << " on " << r.degreesOfFreedom
        << " degrees of freedom, p = " << formatNumber("%.3g", r.p) << " (fails below "
        << formatNumber("%.3g", settings.significance) << "); the pdf integrates to "
        << formatNumber("%.3g", r.pdfIntegral);
    r.verdict = out.str();
  } else {
    r.verdict = describeFailure(r, settings.samples);
  }
  return r;
}

}  // namespace pathway
