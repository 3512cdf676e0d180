#include "grade/light_sampling_fit.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/number_format.h"
#include "grade/statistics.h"
#include "grade/warp_fit.h"
#include "sampling/pcg32.h"

namespace pathway {
namespace {

constexpr double kProbabilityTolerance = 1e-3;
constexpr double kSameDensity = 1e-4;  // relative: one triangle, one density
constexpr double kOnTriangle = 1e-4;   // barycentric slack, and plane distance per √area

struct Barycentric {
  double b0, b1, b2, offPlane;
};

Barycentric barycentricOf(const EmissiveTriangle& e, const Vec3& y) {
  const glm::dvec3 p0(e.p0), e1 = glm::dvec3(e.p1) - p0, e2 = glm::dvec3(e.p2) - p0,
                             v = glm::dvec3(y) - p0;
  const double d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const double d20 = glm::dot(v, e1), d21 = glm::dot(v, e2);
  const double denominator = d00 * d11 - d01 * d01;
  const double b1 = (d11 * d20 - d01 * d21) / denominator;
  const double b2 = (d00 * d21 - d01 * d20) / denominator;
  return {1.0 - b1 - b2, b1, b2, std::fabs(glm::dot(v, glm::dvec3(e.normal)))};
}

// The small triangle holding barycentrics (b1, b2) when the triangle is cut into k² congruent
// ones by lines parallel to its sides: "up" triangles (i, j) with i + j <= k - 1, "down" ones
// (the rest of a lattice square) with i + j <= k - 2. Returns 0 .. k² - 1.
int smallTriangle(double b1, double b2, int k) {
  const double x = std::clamp(b1, 0.0, 1.0) * k, y = std::clamp(b2, 0.0, 1.0) * k;
  int i = std::min(static_cast<int>(x), k - 1), j = std::min(static_cast<int>(y), k - 1);
  const bool down = (x - i) + (y - j) > 1.0 && i + j <= k - 2;
  while (i + j > k - 1) (i > j ? i : j) -= 1;  // a point on the far edge, rounded past it
  // Up triangles first, row by row (row i holds k - i of them), then the down ones.
  const int upBefore = i * k - i * (i - 1) / 2;
  if (!down) return upBefore + j;
  const int downBefore = i * (k - 1) - i * (i - 1) / 2;
  return k * (k + 1) / 2 + downBefore + j;
}

std::string describe(const LightSamplingTestResult& r, long samples,
                     const std::vector<EmissiveTriangle>& emitters,
                     const LightSamplingTestSettings& settings) {
  std::ostringstream out;
  if (r.invalid > 0) {
    out << r.invalid << " of " << samples
        << " points are not on the triangle their LightSample names (or name none, or are NaN)";
    return out.str();
  }
  if (r.notFinite > 0) {
    out << r.notFinite << " of " << samples
        << " points have a pdfArea that is not a finite number (a division by zero?)";
    return out.str();
  }
  if (r.inconsistent > 0) {
    out << r.inconsistent << " of " << samples
        << " points claim another pdfArea than other points of their triangle: a uniform point "
           "has one density per triangle, the pick's probability / its area";
    return out.str();
  }
  if (std::fabs(r.probabilitySum - 1.0) > kProbabilityTolerance) {
    out << "your pdfArea · area, summed over the emitters, is "
        << formatNumber("%.4g", r.probabilitySum)
        << ", not 1: pdfArea must be the probability of choosing the triangle / its area";
    return out.str();
  }
  const double half = settings.significance / 2;
  if (r.pickP < half) {
    size_t worst = 0;
    double worstZ = 0.0;
    for (size_t e = 0; e < r.pickObserved.size(); ++e) {
      if (r.pickExpected[e] <= 0) continue;
      const double z =
          std::fabs(r.pickObserved[e] - r.pickExpected[e]) / std::sqrt(r.pickExpected[e]);
      if (z > worstZ) worstZ = z, worst = e;
    }
    out << "emitter " << worst + 1 << " of " << emitters.size() << " (mesh " << emitters[worst].mesh
        << ", triangle " << emitters[worst].triangle << ") is chosen "
        << formatNumber("%.0f", r.pickObserved[worst]) << " times in " << samples
        << ", where its pdfArea · area says " << formatNumber("%.0f", r.pickExpected[worst])
        << ": the probability in your density is not that of your pick (χ² = "
        << formatNumber("%.3g", r.pickChiSquared) << " on " << r.pickDegrees
        << " degrees of freedom, p = " << formatNumber("%.3g", r.pickP) << ")";
    return out.str();
  }
  const double chance = 3.0 * std::sqrt(1.0 / 18.0) / std::sqrt(static_cast<double>(samples));
  const double shift = r.meanWeightOfP0 - 1.0 / 3.0;
  if (shift > chance)
    out << "your points crowd towards each triangle's first corner p0";
  else if (shift < -chance)
    out << "your points crowd away from each triangle's first corner p0";
  else
    out << "your points are not uniform on their triangles";
  out << " (the mean barycentric weight of p0 is " << formatNumber("%.3g", r.meanWeightOfP0)
      << ", 1/3 for uniform points): χ² = " << formatNumber("%.3g", r.pointChiSquared) << " on "
      << r.pointDegrees << " degrees of freedom, p = " << formatNumber("%.3g", r.pointP);
  return out.str();
}

}  // namespace

LightSamplingTestResult testLightSampling(const LightSampler& sampler, const EmitterPicker& picker,
                                          const std::vector<EmissiveTriangle>& emitters,
                                          const LightSamplingTestSettings& settings) {
  if (settings.samples < 1000 || settings.cellsPerSide < 1)
    throw PathwayError("light sampling test: at least 1000 samples and one cell per side");
  if (emitters.empty() || picker.empty())
    throw PathwayError("light sampling test: the scene has no emitter to sample");
  const int k = settings.cellsPerSide, cells = k * k;
  LightSamplingTestResult r;
  r.emitters = static_cast<int>(emitters.size());
  std::map<std::pair<uint32_t, uint32_t>, size_t> indexOf;
  for (size_t e = 0; e < emitters.size(); ++e)
    indexOf[{emitters[e].mesh, emitters[e].triangle}] = e;
  r.pickObserved.assign(emitters.size(), 0.0);
  r.pointObserved.assign(emitters.size() * cells, 0.0);
  std::vector<double> claimed(emitters.size(), -1.0);  // each emitter's pdfArea, once seen

  Pcg32 random(settings.seed);
  double weightOfP0 = 0.0;
  for (int n = 0; n < settings.samples; ++n) {
    const float uPick = random.nextFloat();
    const Vec2 uPoint(random.nextFloat(), random.nextFloat());
    const LightSample s = sampler(picker, uPick, uPoint);
    const auto found =
        s.emitter ? indexOf.find({s.emitter->mesh, s.emitter->triangle}) : indexOf.end();
    if (found == indexOf.end() || !std::isfinite(s.position.x) || !std::isfinite(s.position.y) ||
        !std::isfinite(s.position.z)) {
      ++r.invalid;
      continue;
    }
    if (!std::isfinite(s.pdfArea)) {
      ++r.notFinite;
      continue;
    }
    const size_t e = found->second;
    const EmissiveTriangle& triangle = emitters[e];
    const Barycentric b = barycentricOf(triangle, s.position);
    if (b.b0 < -kOnTriangle || b.b1 < -kOnTriangle || b.b2 < -kOnTriangle ||
        b.offPlane > kOnTriangle * std::sqrt(double(triangle.area))) {
      ++r.invalid;
      continue;
    }
    if (claimed[e] < 0.0)
      claimed[e] = s.pdfArea;
    else if (std::fabs(s.pdfArea - claimed[e]) > kSameDensity * std::fabs(claimed[e]))
      ++r.inconsistent;
    r.pickObserved[e] += 1.0;
    r.pointObserved[e * cells + smallTriangle(b.b1, b.b2, k)] += 1.0;
    weightOfP0 += b.b0;
  }
  const long valid = settings.samples - r.invalid - r.notFinite;
  r.meanWeightOfP0 = valid > 0 ? weightOfP0 / valid : 0.0;

  // Which emitter: the claimed probability of each, from its density (0 for one never drawn,
  // whose claim is unknown; the sum then falls short of 1 by what it should have had).
  r.pickExpected.assign(emitters.size(), 0.0);
  for (size_t e = 0; e < emitters.size(); ++e) {
    if (claimed[e] < 0.0) continue;
    const double probability = claimed[e] * emitters[e].area;
    r.probabilitySum += probability;
    r.pickExpected[e] = probability * valid;
  }
  r.pickChiSquared = pooledChiSquared(r.pickObserved, r.pickExpected, r.pickDegrees);
  r.pickP = r.pickDegrees > 0 ? chiSquaredUpperTail(r.pickChiSquared, r.pickDegrees) : 1.0;

  // Where on the triangle, given how often it was chosen: k² equal parts of it.
  r.pointExpected.assign(r.pointObserved.size(), 0.0);
  for (size_t e = 0; e < emitters.size(); ++e) {
    if (r.pickObserved[e] <= 0.0) continue;
    const std::vector<double> observed(r.pointObserved.begin() + e * cells,
                                       r.pointObserved.begin() + (e + 1) * cells);
    const std::vector<double> expected(cells, r.pickObserved[e] / cells);
    std::copy(expected.begin(), expected.end(), r.pointExpected.begin() + e * cells);
    int degrees = 0;
    r.pointChiSquared += pooledChiSquared(observed, expected, degrees);
    r.pointDegrees += degrees;
  }
  r.pointP = r.pointDegrees > 0 ? chiSquaredUpperTail(r.pointChiSquared, r.pointDegrees) : 1.0;

  const double half = settings.significance / 2;
  r.passed = r.invalid == 0 && r.notFinite == 0 && r.inconsistent == 0 &&
             std::fabs(r.probabilitySum - 1.0) <= kProbabilityTolerance && r.pickP >= half &&
             r.pointP >= half;
  if (r.passed) {
    std::ostringstream out;
    out << "passed: which emitter χ² = " << formatNumber("%.3g", r.pickChiSquared) << " on "
        << r.pickDegrees << " degrees of freedom (p = " << formatNumber("%.3g", r.pickP)
        << "), where on it χ² = " << formatNumber("%.3g", r.pointChiSquared) << " on "
        << r.pointDegrees << " (p = " << formatNumber("%.3g", r.pointP) << "); fails below "
        << formatNumber("%.3g", half) << " each; pdfArea · area sums to "
        << formatNumber("%.4g", r.probabilitySum);
    r.verdict = out.str();
  } else {
    r.verdict = describe(r, settings.samples, emitters, settings);
  }
  return r;
}

}  // namespace pathway
