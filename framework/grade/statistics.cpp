// Tail probabilities for the autograder (see statistics.h). Everything is computed so that the
// small side of a probability is never formed as 1 - (something close to 1).
#include "grade/statistics.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <string>

#include "core/error.h"

namespace pathway {
namespace {

constexpr double kInvSqrt2 = 0.70710678118654752440;
constexpr double kInvSqrt2Low = -4.8336466567264565e-17;  // 1/sqrt(2) - kInvSqrt2
constexpr double kTwoOverSqrtPi = 1.12837916709551257390;
constexpr double kSqrt2Pi = 2.50662827463100050242;
constexpr double kLogSqrt2Pi = 0.91893853320467274178;
constexpr double kEpsilon = 1e-15;      // series and continued fractions stop at this relative step
constexpr int kMaxIterations = 100000;  // they need at most O(sqrt(shape)) terms (near the mean)
constexpr double kTiny = 1e-300;        // modified Lentz: replaces a vanishing denominator

// erfc(z / sqrt(2)). Rounding z / sqrt(2) to x would cost a relative 2 x² * 1e-16 (1e-13 at
// z = 37); the rounding error h is recovered with fma and corrected to first order.
double erfcOfScaled(double z) {
  const double x = z * kInvSqrt2;
  const double h = std::fma(z, kInvSqrt2, -x) + z * kInvSqrt2Low;
  return std::erfc(x) - h * kTwoOverSqrtPi * std::exp(-x * x);
}

[[noreturn]] void notConverged(const char* what) {
  throw PathwayError(std::string(what) + ": no convergence (shape parameter out of range)");
}

// Remainder of Stirling's series: lgamma(x) = (x - 1/2) ln x - x + ln sqrt(2 pi) + stirlingTail(x),
// error < 2e-14 for x >= 10. lgamma(5e5) ~ 6e6 carries an absolute error ~1e-9, which a difference
// of two lgammas turns into a 1e-9 relative error in p; through this tail all terms stay small.
double stirlingTail(double x) {
  const double r = 1 / (x * x);
  return (1.0 / 12 - r * (1.0 / 360 - r * (1.0 / 1260 - r * (1.0 / 1680 - r / 1188)))) / x;
}

// ln B(a, b) without subtracting huge lgamma values when a shape is large.
double logBeta(double a, double b) {
  const double p = std::min(a, b), q = std::max(a, b), s = a + b;
  if (q < 10) return std::lgamma(p) + std::lgamma(q) - std::lgamma(s);
  if (p < 10) {  // lgamma(s) - lgamma(q), expanded
    return std::lgamma(p) - (q - 0.5) * std::log1p(p / q) - p * (std::log(s) - 1) -
           stirlingTail(s) + stirlingTail(q);
  }
  return kLogSqrt2Pi - 0.5 * std::log(s) + (p - 0.5) * std::log(p / s) -
         (q - 0.5) * std::log1p(p / q) + stirlingTail(p) + stirlingTail(q) - stirlingTail(s);
}

// Continued fraction for I_x(a, b) (Numerical Recipes' betacf, modified Lentz), y = 1 - x.
// With x near 1 and a large, every odd coefficient d is ~ -1 and the textbook updates 1 + d D and
// 1 + d / C cancel ~a-fold (2e-11 at nu = 1e6). They are rewritten around 1 + d, computed from y.
double betaFraction(double x, double y, double a, double b) {
  auto clampTiny = [](double v) { return std::fabs(v) < kTiny ? kTiny : v; };
  auto onePlusOdd = [&](int m) {  // 1 - (a + m)(a + b + m) x / ((a + 2m)(a + 2m + 1))
    const double denominator = (a + 2 * m) * (a + 2 * m + 1);
    if (x < 0.5) return 1 - (a + m) * (a + b + m) * x / denominator;
    return (a * (2 * m + 1 - b) + m * (3.0 * m + 2 - b) + (a + m) * (a + b + m) * y) / denominator;
  };
  double c = 1, d = 1 / clampTiny(onePlusOdd(0)), h = d;
  for (int m = 1; m <= kMaxIterations; ++m) {
    const double even = m * (b - m) * x / ((a + 2 * m - 1) * (a + 2 * m));
    const double evenD = even * d, evenC = even / c;
    const double dEven = 1 / clampTiny(1 + evenD), cEven = clampTiny(1 + evenC);
    h *= dEven * cEven;
    // Odd step: 1 + odd * dEven = (1 + odd + evenD) * dEven, 1 + odd / cEven likewise.
    const double odd1 = onePlusOdd(m);
    d = 1 / (clampTiny(odd1 + evenD) * dEven);
    c = clampTiny(odd1 + evenC) / cEven;
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1) < kEpsilon) return h;
  }
  notConverged("regularizedIncompleteBeta");
}

struct Split {
  double lower, upper;  // a probability and its complement, the smaller one computed directly
};

// I_x(a, b) and 1 - I_x(a, b) from x, y = 1 - x and their logs, which callers pass in because they
// may know them more accurately than 1 - x (and ln x even where x underflows).
Split incompleteBeta(double x, double y, double lx, double ly, double a, double b) {
  // x^a y^b / B(a, b) in log space: it can only underflow in the final exp.
  const double front = std::exp(a * lx + b * ly - logBeta(a, b));
  // The fraction converges fast below the mean; above it use I_x(a, b) = 1 - I_y(b, a).
  if (x * (a + b + 2) < a + 1) {
    const double v = front * betaFraction(x, y, a, b) / a;
    return {v, 1 - v};
  }
  const double v = front * betaFraction(y, x, b, a) / b;
  return {1 - v, v};
}

// {P(|T| > |t|), P(|T| < |t|)} = {I_x(nu/2, 1/2), I_y(1/2, nu/2)}, x = 1/(1+r), y = r/(1+r),
// r = t²/nu. x, y and their logs come from r directly (never 1 - x), and ln r from logs when r
// overflows, so tails stay exact out to t ~ 1e300.
Split studentTSplit(double t, double nu) {
  if (!(nu > 0)) throw PathwayError("Student's t needs nu > 0 degrees of freedom");
  if (std::isnan(t)) return {t, t};
  if (std::isinf(nu)) return {normalTwoSidedP(t), std::erf(std::fabs(t) * kInvSqrt2)};
  const double r = (t / nu) * t;
  const double lr = std::isnormal(r) ? std::log(r) : 2 * std::log(std::fabs(t)) - std::log(nu);
  const bool small = r < 1;
  const double x = small ? 1 / (1 + r) : (1 / r) / (1 + 1 / r);
  const double y = small ? r / (1 + r) : 1 / (1 + 1 / r);
  const double lx = small ? -std::log1p(r) : -lr - std::log1p(1 / r);
  const double ly = small ? lr - std::log1p(r) : -std::log1p(1 / r);
  return incompleteBeta(x, y, lx, ly, 0.5 * nu, 0.5);
}

// ln(x^a e^-x / Gamma(a)), the factor shared by the series and the continued fraction for Q.
double logGammaFront(double a, double x) {
  if (a < 10) return a * std::log(x) - x - std::lgamma(a);
  // a ln x - x and lgamma(a) are both ~a ln a (5e5 at k = 1e5) and nearly cancel; with Stirling the
  // difference is -a (d - ln(1 + d)), d = (x - a)/a, whose absolute error is only |x - a| * 1e-16.
  const double d = (x - a) / a;
  return -a * (d - std::log1p(d)) + 0.5 * std::log(a) - kLogSqrt2Pi - stirlingTail(a);
}

// Acklam's rational approximation (relative error < 1.15e-9) for the quantile x <= 0 of
// q = 0.5 - d <= 0.5, refined by one Halley step (cubic: error ~1e-27, i.e. rounding only). d is
// passed separately so that quantiles near the median keep full relative accuracy.
template <int N>
double horner(const double (&c)[N], double x) {
  double v = c[0];
  for (int i = 1; i < N; ++i) v = v * x + c[i];
  return v;
}

double lowerQuantile(double q, double d) {
  constexpr double kA[] = {-3.969683028665376e+01, 2.209460984245205e+02,  -2.759285104469687e+02,
                           1.383577518672690e+02,  -3.066479806614716e+01, 2.506628277459239e+00};
  constexpr double kB[] = {-5.447609879822406e+01, 1.615858368580409e+02,  -1.556989798598866e+02,
                           6.680131188771972e+01,  -1.328068155288572e+01, 1};
  constexpr double kC[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                           -2.549732539343734e+00, 4.374664141464968e+00,  2.938163982698783e+00};
  constexpr double kD[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                           3.754408661907416e+00, 1};
  constexpr double kLow = 0.02425;  // below this the tail form is used
  double x;
  if (q < kLow) {
    const double s = std::sqrt(-2 * std::log(q));
    x = horner(kC, s) / horner(kD, s);
  } else {
    const double s = -d;
    x = s * horner(kA, s * s) / horner(kB, s * s);
  }
  // A subnormal q has too few bits for the refinement to improve on Acklam.
  if (q < DBL_MIN) return x;
  // Residual Phi(x) - q: erfc keeps it relative in the tail, erf keeps it relative near the median.
  const double e = q < kLow ? 0.5 * erfcOfScaled(-x) - q : 0.5 * std::erf(x * kInvSqrt2) + d;
  // u = e / phi(x); exp(x²/2) is split in two so that it cannot overflow for |x| up to 38.5.
  const double half = std::exp(0.25 * x * x);
  const double u = e * half * half * kSqrt2Pi;
  return x - u / (1 + 0.5 * x * u);
}

}  // namespace

double normalCdf(double z) {
  return 0.5 * erfcOfScaled(-z);
}

double normalTwoSidedP(double z) {
  return erfcOfScaled(std::fabs(z));
}

double normalQuantile(double p) {
  if (!(p > 0 && p < 1)) throw PathwayError("normalQuantile needs 0 < p < 1");
  // Work on the lower half; 1 - p and p - 1/2 are exact for p >= 1/4 (Sterbenz).
  return p > 0.5 ? -lowerQuantile(1 - p, p - 0.5) : lowerQuantile(p, 0.5 - p);
}

double regularizedIncompleteBeta(double x, double a, double b) {
  if (!(x >= 0 && x <= 1 && a > 0 && b > 0)) {
    throw PathwayError("regularizedIncompleteBeta needs 0 <= x <= 1 and a, b > 0");
  }
  return incompleteBeta(x, 1 - x, std::log(x), std::log1p(-x), a, b).lower;
}

double regularizedUpperGamma(double a, double x) {
  if (!(a > 0)) throw PathwayError("regularizedUpperGamma needs a > 0");
  if (std::isnan(x)) return x;
  if (x <= 0) return 1;
  if (std::isinf(x)) return 0;
  const double front = std::exp(logGammaFront(a, x));
  if (x < a + 1) {
    // Series for P(a, x). Q = 1 - P loses nothing here: Q(a, x < a + 1) > 0.08 for a >= 1/2.
    double term = 1 / a, sum = term;
    for (int n = 1; std::fabs(term) > sum * kEpsilon; ++n) {
      if (n > kMaxIterations) notConverged("regularizedUpperGamma");
      term *= x / (a + n);
      sum += term;
    }
    return 1 - front * sum;
  }
  // Continued fraction for Q itself (modified Lentz), fast for x >= a + 1.
  double b = x + 1 - a, c = 1 / kTiny, d = 1 / b, h = d;
  for (int i = 1; i <= kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2;
    d = an * d + b;
    d = 1 / (std::fabs(d) < kTiny ? kTiny : d);
    c = b + an / c;
    c = std::fabs(c) < kTiny ? kTiny : c;
    const double step = d * c;
    h *= step;
    if (std::fabs(step - 1) < kEpsilon) return front * h;
  }
  notConverged("regularizedUpperGamma");
}

double studentTTwoSidedP(double t, double nu) {
  return studentTSplit(t, nu).lower;
}

double studentTToNormal(double t, double nu) {
  const Split split = studentTSplit(t, nu);
  if (std::isnan(t)) return t;
  // One-sided tail q = P/2 and 0.5 - q = C/2 (C = P(|T| < |t|) computed directly for small t).
  const double q = 0.5 * split.lower;
  if (!(q > 0)) return std::copysign(kMaxTransformedZ, t);  // underflowed
  return std::copysign(std::min(-lowerQuantile(q, 0.5 * split.upper), kMaxTransformedZ), t);
}

double chiSquaredUpperTail(double x, double k) {
  if (!(k > 0)) throw PathwayError("chiSquaredUpperTail needs k > 0 degrees of freedom");
  return regularizedUpperGamma(0.5 * k, 0.5 * x);
}

double chiSquaredLowerTail(double x, double k) {
  if (!(k > 0)) throw PathwayError("chiSquaredLowerTail needs k > 0 degrees of freedom");
  const double a = 0.5 * k, half = 0.5 * x;
  if (std::isnan(x)) return x;
  if (half <= 0) return 0;
  if (half >= a + 1) return 1 - regularizedUpperGamma(a, half);  // P is not small there
  // The series for P(a, x) itself: no cancellation however small P is.
  double term = 1 / a, sum = term;
  for (int n = 1; std::fabs(term) > sum * kEpsilon; ++n) {
    if (n > kMaxIterations) notConverged("chiSquaredLowerTail");
    term *= half / (a + n);
    sum += term;
  }
  return std::exp(logGammaFront(a, half)) * sum;
}

double sidakPerTestAlpha(double familyAlpha, double tests) {
  if (!(familyAlpha >= 0 && familyAlpha <= 1 && tests > 0)) {
    throw PathwayError("sidakPerTestAlpha needs 0 <= alpha <= 1 and tests > 0");
  }
  // 1 - (1 - alpha)^(1/m) literally would round 1 - alpha and then cancel: log1p/expm1 do not.
  return -std::expm1(std::log1p(-familyAlpha) / tests);
}

double sidakFamilyP(double minP, double tests) {
  if (!(minP >= 0 && minP <= 1 && tests > 0)) {
    throw PathwayError("sidakFamilyP needs 0 <= p <= 1 and tests > 0");
  }
  return -std::expm1(tests * std::log1p(-minP));
}

double welchDegreesOfFreedom(double a, double nuA, double b, double nuB) {
  if (!(a >= 0.0 && b >= 0.0 && nuA > 0.0 && nuB > 0.0))
    throw PathwayError("Welch-Satterthwaite needs variances >= 0 and degrees of freedom > 0");
  const double spread = a * a / nuA + b * b / nuB;
  return spread > 0.0 ? (a + b) * (a + b) / spread : nuA + nuB;
}

}  // namespace pathway
