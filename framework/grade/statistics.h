// Tail probabilities for the autograder's tile tests, in double precision and accurate far out in
// the tails (p down to 1e-300), where `1 - cdf` would have cancelled to 0 long before.
//
// Each tile gives t = (m_s - m_r) / sqrt(V (1 + 1/R) + floor²) with V estimated from R reference
// replicates, so under the null hypothesis t ~ Student's t with nu = R - 1. Thousands of tiles are
// tested at once (Šidák correction), and omnibus tests map t to N(0,1) first (studentTToNormal).
#pragma once

namespace pathway {

// Relative accuracies below were measured against mpmath at 50 digits (tests/statistics_test.cpp).

// Standard normal: P(Z <= z), and P(|Z| > |z|) from erfc, never 1 - cdf (relative error ~2e-16 out
// to |z| = 38, where the tail underflows).
double normalCdf(double z);
double normalTwoSidedP(double z);
// Inverse of normalCdf: relative error ~3e-16 in z for p in [1e-300, 1 - 1e-16], still ~1e-9 for
// subnormal p. Throws PathwayError unless 0 < p < 1.
double normalQuantile(double p);

// I_x(a, b), the regularized incomplete beta function, for 0 <= x <= 1 and a, b > 0 (continued
// fraction; ~5e-14 relative when min(a, b) is small, as for Student's t; with both shapes large
// the error grows to ~(a + b) * 1e-16 relative). Throws PathwayError otherwise.
double regularizedIncompleteBeta(double x, double a, double b);
// Q(a, x) = Γ(a, x) / Γ(a), the regularized upper incomplete gamma function, for a > 0 (x <= 0
// gives 1): ~1e-13 relative in the upper tail for a up to 5e4. Throws PathwayError unless a > 0.
double regularizedUpperGamma(double a, double x);

// P(|T_nu| > |t|) for Student's t with nu > 0 degrees of freedom; nu = inf gives the normal.
// Relative error ~5e-14 for nu in [1, 2e6] and tails down to 1e-300 (it tends to the normal for
// larger nu); 0 only where the true value is below ~5e-324. Throws PathwayError unless nu > 0.
double studentTTwoSidedP(double t, double nu);
// The probability-integral transform: the z with the sign of t and
// normalTwoSidedP(z) == studentTTwoSidedP(t, nu), relative error ~3e-15 (also for tiny t). Where
// that probability underflows, ±kMaxTransformedZ instead (never inf; nan stays nan).
constexpr double kMaxTransformedZ = 38.5;  // beyond the quantile of every positive double (38.47)
double studentTToNormal(double t, double nu);

// Welch–Satterthwaite: the degrees of freedom of a + b, two independent variance estimates with
// nuA and nuB degrees of freedom: (a + b)² / (a²/nuA + b²/nuB), between min(nuA, nuB) and
// nuA + nuB. A zero estimate adds none (both zero: nuA + nuB). Throws PathwayError unless a, b >= 0
// and nuA, nuB > 0.
double welchDegreesOfFreedom(double a, double nuA, double b, double nuB);

// P(χ²_k > x) = Q(k/2, x/2), k > 0 degrees of freedom (x <= 0 gives 1). Throws PathwayError unless
// k > 0.
double chiSquaredUpperTail(double x, double k);
// P(χ²_k <= x) = P(k/2, x/2), accurate where it is tiny (an image far closer to the reference than
// chance allows). Throws PathwayError unless k > 0.
double chiSquaredLowerTail(double x, double k);

// Šidák correction for m independent tests: the per-test level 1 - (1 - alpha)^(1/m) that keeps
// the family-wise error at alpha, and the family-wise p-value 1 - (1 - p_min)^m of the smallest
// of m p-values; both stay accurate for tiny alpha and p. Throw PathwayError unless the
// probability is in [0, 1] and tests > 0.
double sidakPerTestAlpha(double familyAlpha, double tests);
double sidakFamilyP(double minP, double tests);

}  // namespace pathway
