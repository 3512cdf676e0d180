// The grader's tail probabilities against independently computed reference values.
//
// Unless a test says otherwise, the reference values were computed with mpmath 1.4.1 at 50
// significant digits (printed to 17) from the exact double inputs: erfc / ncdf for the normal,
// findroot on log(ncdf(x)) = log(p) for its quantile, betainc(nu/2, 1/2, 0, nu/(nu+t^2),
// regularized=True) for Student's t (cross-checked against quadrature of the density and the
// 2F1 form of I_x), gammainc(k/2, x/2, inf, regularized=True) for chi-squared, and the Šidák
// formulas evaluated literally at 50 digits. A few were spot-checked against scipy 1.17 as well.
#include "grade/statistics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/error.h"

namespace pathway {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

::testing::AssertionResult relativelyNear(double actual, double expected, double tolerance) {
  const double error = std::fabs(actual - expected) / std::fabs(expected);
  if (error <= tolerance) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual " << actual << " expected " << expected
                                       << " relative error " << error << " > " << tolerance;
}

TEST(Statistics, NormalTailsMatchReference) {
  struct Case {
    double z, twoSided, lower;  // P(|Z| > z), P(Z < -z)
  };
  const Case cases[] = {
      {1, 3.173105078629141e-1, 1.5865525393145705e-1},
      {5.11, 3.2215881224427482e-7, 1.6107940612213741e-7},
      {8, 1.2441921148543568e-15, 6.2209605742717841e-16},
      {20, 5.5072482372124674e-89, 2.7536241186062337e-89},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.z);
    EXPECT_TRUE(relativelyNear(normalTwoSidedP(c.z), c.twoSided, 1e-14));
    EXPECT_TRUE(relativelyNear(normalTwoSidedP(-c.z), c.twoSided, 1e-14));
    EXPECT_TRUE(relativelyNear(normalCdf(-c.z), c.lower, 1e-14));
  }
  EXPECT_TRUE(relativelyNear(normalCdf(1), 1 - 1.5865525393145705e-1, 1e-15));
  EXPECT_EQ(normalCdf(0), 0.5);
  EXPECT_EQ(normalTwoSidedP(0), 1);
}

TEST(Statistics, NormalQuantileMatchesReference) {
  EXPECT_EQ(normalQuantile(0.5), 0);
  EXPECT_TRUE(relativelyNear(normalQuantile(1e-3), -3.0902323061678135, 1e-14));
  EXPECT_TRUE(relativelyNear(normalQuantile(1e-12), -7.0344838253011319, 1e-14));
  EXPECT_TRUE(relativelyNear(normalQuantile(1e-300), -3.7047096299361199e+1, 1e-14));
  // 0.999 is the double 1 - 0.0010000000000000009, hence the last digit.
  EXPECT_TRUE(relativelyNear(normalQuantile(0.999), 3.0902323061678133, 1e-14));
  EXPECT_TRUE(relativelyNear(normalQuantile(0.975), 1.9599639845400539, 1e-14));
}

TEST(Statistics, NormalQuantileRoundTripsThroughTheCdf) {
  for (double p : {0.5, 0.3, 0.1, 0.02425, 0.02, 1e-3, 1e-12, 1e-100, 1e-200, 1e-300}) {
    SCOPED_TRACE(p);
    EXPECT_TRUE(relativelyNear(normalCdf(normalQuantile(p)), p, 1e-13));
    // The upper half: the double 1 - p has the exact upper tail 1 - (1 - p).
    if (1 - p < 1) {
      EXPECT_TRUE(relativelyNear(normalCdf(-normalQuantile(1 - p)), 1 - (1 - p), 1e-13));
    }
  }
  // Close to 1 the upper tail is tiny; 1 - 1e-16 rounds to 1 - 2^-53.
  const double nearOne = 1 - 1e-16;
  EXPECT_TRUE(relativelyNear(normalCdf(-normalQuantile(nearOne)), 1 - nearOne, 1e-13));
  // Monotone over the whole range, including subnormal p (refinement off there, no blow-up).
  double previous = -kInf;
  for (double p = 4.9e-324; p < 0.5; p *= 3.7) {
    const double z = normalQuantile(p);
    EXPECT_TRUE(std::isfinite(z)) << p;
    EXPECT_GT(z, previous) << p;
    previous = z;
  }
  for (double bad : {0.0, 1.0, -0.5, 2.0, kNaN}) {
    EXPECT_THROW(normalQuantile(bad), PathwayError) << bad;
  }
}

TEST(Statistics, StudentTTailsMatchReference) {
  const double ts[] = {2, 5.11, 8, 30};
  struct Row {
    double nu, p[4];  // P(|T_nu| > t) for each t above
  };
  const Row rows[] = {
      {1,
       {2.9516723530086655e-1, 1.2302833542601958e-1, 7.9166848321131084e-2,
        2.1212804811070847e-2}},
      {5,
       {1.0193947882985836e-1, 3.7384904672887464e-3, 4.9290666057244408e-4, 7.718648620496052e-7}},
      {31,
       {5.4327215367175708e-2, 1.5668819270645464e-5, 4.9402637019033796e-9,
        1.8073614889644536e-24}},
      {63,
       {4.9815763699044806e-2, 3.2243118846191671e-6, 3.5679286547882802e-11,
        5.1259117730576128e-39}},
      {1e6,
       {4.5500533851319208e-2, 3.2221787667636475e-7, 1.245506343320252e-15,
        1.2020094233663438e-197}},
  };
  for (const Row& row : rows) {
    for (int i = 0; i < 4; ++i) {
      SCOPED_TRACE(testing::Message() << "nu " << row.nu << " t " << ts[i]);
      EXPECT_TRUE(relativelyNear(studentTTwoSidedP(ts[i], row.nu), row.p[i], 1e-12));
      EXPECT_EQ(studentTTwoSidedP(-ts[i], row.nu), studentTTwoSidedP(ts[i], row.nu));
    }
  }
}

TEST(Statistics, StudentTApproachesTheNormal) {
  for (double t : {0.5, 2.0, 5.11, 8.0}) {
    EXPECT_EQ(studentTTwoSidedP(t, kInf), normalTwoSidedP(t));
    // Heavier tails than the normal, by a factor 1 + O(t^4 / nu).
    const double ratio = studentTTwoSidedP(t, 1e6) / normalTwoSidedP(t);
    EXPECT_GT(ratio, 1) << t;
    EXPECT_LT(ratio, 1 + (t * t * t * t + 1) / 1e6) << t;
  }
}

TEST(Statistics, StudentTEdgeCases) {
  EXPECT_EQ(studentTTwoSidedP(0, 63), 1);
  EXPECT_EQ(studentTTwoSidedP(0, 1e6), 1);
  // Far tails stay exact where t^2 / nu overflows: P ~ 2 / (pi t) for nu = 1.
  EXPECT_TRUE(relativelyNear(studentTTwoSidedP(1e200, 1), 6.3661977236758136e-201, 1e-13));
  EXPECT_TRUE(relativelyNear(studentTTwoSidedP(1e3, 63), 4.7744703949322694e-134, 1e-12));
  // The true value, 4.8e-575, is below the smallest double.
  EXPECT_EQ(studentTTwoSidedP(1e10, 63), 0);
  EXPECT_EQ(studentTTwoSidedP(kInf, 63), 0);
  EXPECT_TRUE(std::isnan(studentTTwoSidedP(kNaN, 63)));
  for (double bad : {0.0, -1.0, kNaN}) {
    EXPECT_THROW(studentTTwoSidedP(1, bad), PathwayError) << bad;
    EXPECT_THROW(studentTToNormal(1, bad), PathwayError) << bad;
  }
}

TEST(Statistics, StudentTToNormalMatchesReference) {
  // z = -Phi^-1(P / 2) for P = P(|T_63| > t), from the reference P at 50 digits.
  EXPECT_TRUE(relativelyNear(studentTToNormal(5.11, 63), 4.6559876971406325, 1e-13));
  EXPECT_TRUE(relativelyNear(studentTToNormal(-5.11, 63), -4.6559876971406325, 1e-13));
  EXPECT_TRUE(relativelyNear(studentTToNormal(30, 63), 1.3066361690967511e+1, 1e-13));
  EXPECT_EQ(studentTToNormal(0, 63), 0);
  // Where the tail underflows the documented clamp applies, with the sign of t.
  EXPECT_EQ(studentTToNormal(1e10, 63), kMaxTransformedZ);
  EXPECT_EQ(studentTToNormal(-1e10, 63), -kMaxTransformedZ);
  EXPECT_EQ(studentTToNormal(kInf, 63), kMaxTransformedZ);
  EXPECT_EQ(studentTToNormal(-kInf, 63), -kMaxTransformedZ);
  EXPECT_TRUE(std::isnan(studentTToNormal(kNaN, 63)));
  // Small t keeps its relative accuracy (the central probability is computed directly):
  // z = sqrt(2) erfinv(P(|T| < t)), with P(|T_1| < t) = (2/pi) atan(t) (mpmath, 50 digits).
  EXPECT_TRUE(relativelyNear(studentTToNormal(1e-9, 1), 7.9788456080286541e-10, 1e-13));
  EXPECT_TRUE(relativelyNear(studentTToNormal(1e-3, 63), 9.960397711251388e-4, 1e-13));
  // For huge nu the transform is (almost) the identity.
  EXPECT_NEAR(studentTToNormal(3, 1e6), 3, 1e-5);
}

TEST(Statistics, TransformRoundTripIsConsistentForNu63) {
  const double nu = 63;
  double previous = 0;
  // From the centre out to two-sided tails of 1e-300 (t ~ 3e5).
  for (double t = 0.01, p = 1; p > 1e-300; t *= 1.07) {
    SCOPED_TRACE(t);
    p = studentTTwoSidedP(t, nu);
    const double z = studentTToNormal(t, nu);
    ASSERT_GT(p, 0);
    EXPECT_GT(z, previous);
    previous = z;
    // Same two-sided tail, and the quantile of P/2 gives back -z.
    EXPECT_TRUE(relativelyNear(normalTwoSidedP(z), p, 1e-12));
    EXPECT_TRUE(relativelyNear(-normalQuantile(0.5 * p), z, p < 0.5 ? 1e-14 : 1e-9));
    EXPECT_EQ(studentTToNormal(-t, nu), -z);
  }
  EXPECT_GT(previous, 37);  // reached p ~ 1e-300 without clamping
  EXPECT_LE(previous, kMaxTransformedZ);
}

TEST(Statistics, ChiSquaredUpperTailMatchesReference) {
  struct Case {
    double x, k, q;
  };
  const Case cases[] = {
      {0.5, 1, 4.7950012218695346e-1},
      {1, 1, 3.173105078629141e-1},
      {1 + 5 * std::sqrt(2.0), 1, 4.4977603796809946e-3},
      {1 + 20 * std::sqrt(2.0), 1, 6.2500962080453123e-8},
      {100, 1, 1.5239706048321052e-23},
      {5, 10, 8.9117801891415124e-1},
      {10, 10, 4.4049328506521241e-1},
      {10 + 5 * std::sqrt(20.0), 10, 3.4860850171631902e-4},
      {10 + 20 * std::sqrt(20.0), 10, 7.0449685707822676e-17},
      {3072, 3072, 4.9660691474611101e-1},
      {3072 + 5 * std::sqrt(6144.0), 3072, 7.5339596192749559e-7},
      {3072 + 20 * std::sqrt(6144.0), 3072, 8.4714055190358404e-68},
      {1e5 + 5 * std::sqrt(2e5), 1e5, 3.4403880068366017e-7},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "k " << c.k << " x " << c.x);
    EXPECT_TRUE(relativelyNear(chiSquaredUpperTail(c.x, c.k), c.q, 1e-12));
  }
  // k = 2 is the exponential distribution: Q = exp(-x/2) (values: mpmath exp at 50 digits).
  EXPECT_TRUE(relativelyNear(chiSquaredUpperTail(1, 2), 0.60653065971263342, 1e-14));
  EXPECT_TRUE(relativelyNear(chiSquaredUpperTail(1000, 2), 7.1245764067412855e-218, 1e-13));
  EXPECT_NEAR(chiSquaredUpperTail(1536, 3072), 1, 1e-15);
  EXPECT_EQ(chiSquaredUpperTail(0, 10), 1);
  EXPECT_EQ(chiSquaredUpperTail(-3, 10), 1);
  EXPECT_EQ(chiSquaredUpperTail(kInf, 10), 0);
  EXPECT_THROW(chiSquaredUpperTail(1, 0), PathwayError);
  EXPECT_THROW(chiSquaredUpperTail(1, kNaN), PathwayError);
}

TEST(Statistics, ChiSquaredLowerTailMatchesMpmathFarIntoTheTail) {
  struct Case {
    double x, k, p;  // P(a = k/2, x/2), mpmath gammainc(regularized=True) at 30 digits
  };
  const Case cases[] = {
      {0.5, 10, 6.611710561034247e-6},  {0.001, 4, 1.2495834114479178e-7},
      {100, 300, 3.53061222541479e-30}, {250, 300, 0.016197049792355001},
      {3, 1, 0.9167354833364496},       {0.2, 150, 3.6519988687261856e-185},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(testing::Message() << "k " << c.k << " x " << c.x);
    // 1e-11: the prefactor x^a e^-x / Γ(a + 1) carries lgamma's rounding at a = 75.
    EXPECT_TRUE(relativelyNear(chiSquaredLowerTail(c.x, c.k), c.p, 1e-11));
  }
  EXPECT_EQ(chiSquaredLowerTail(0, 10), 0);
  EXPECT_EQ(chiSquaredLowerTail(kInf, 10), 1);
  EXPECT_THROW(chiSquaredLowerTail(1, 0), PathwayError);
}

TEST(Statistics, IncompleteBetaBasics) {
  // I_0.3(2, 3) = 0.3483 exactly (a polynomial in x); I_1e-5(1/2, 1/2) = (2/pi) asin(sqrt(1e-5)).
  EXPECT_TRUE(relativelyNear(regularizedIncompleteBeta(0.3, 2, 3), 0.3483, 1e-14));
  EXPECT_TRUE(
      relativelyNear(regularizedIncompleteBeta(1e-5, 0.5, 0.5), 2.0131718394753873e-3, 1e-14));
  for (double x : {0.01, 0.2, 0.5, 0.9, 0.999}) {
    EXPECT_TRUE(relativelyNear(regularizedIncompleteBeta(x, 1, 1), x, 1e-14)) << x;
    EXPECT_NEAR(regularizedIncompleteBeta(x, 3.5, 40) + regularizedIncompleteBeta(1 - x, 40, 3.5),
                1, 1e-14)
        << x;
  }
  EXPECT_EQ(regularizedIncompleteBeta(0, 2, 3), 0);
  EXPECT_EQ(regularizedIncompleteBeta(1, 2, 3), 1);
  EXPECT_THROW(regularizedIncompleteBeta(1.5, 2, 3), PathwayError);
  EXPECT_THROW(regularizedIncompleteBeta(0.5, 0, 3), PathwayError);
  EXPECT_THROW(regularizedUpperGamma(0, 1), PathwayError);
}

TEST(Statistics, SidakCorrection) {
  EXPECT_TRUE(relativelyNear(sidakPerTestAlpha(1e-3, 3072), 3.2568364930345859e-7, 1e-14));
  EXPECT_TRUE(relativelyNear(sidakFamilyP(1e-9, 3072), 3.0719952829488273e-6, 1e-14));
  // 1 - (1 - 1e-20)^m literally would be 0.
  EXPECT_TRUE(relativelyNear(sidakFamilyP(1e-20, 3072), 3.0719999999999998e-17, 1e-14));
  EXPECT_TRUE(relativelyNear(sidakFamilyP(sidakPerTestAlpha(0.01, 9216), 9216), 0.01, 1e-13));
  EXPECT_TRUE(relativelyNear(sidakPerTestAlpha(0.05, 1), 0.05, 1e-15));
  EXPECT_EQ(sidakFamilyP(0, 3072), 0);
  EXPECT_EQ(sidakFamilyP(1, 3072), 1);
  EXPECT_THROW(sidakPerTestAlpha(1.5, 10), PathwayError);
  EXPECT_THROW(sidakPerTestAlpha(0.01, 0), PathwayError);
  EXPECT_THROW(sidakFamilyP(-0.1, 10), PathwayError);
}

TEST(Statistics, WelchDegreesOfFreedomFollowTheFormula) {
  // (a + b)² / (a²/nuA + b²/nuB): 2 and 1 with 7 and 63 -> 9 / (4/7 + 1/63) = 15.3 (by hand).
  EXPECT_NEAR(welchDegreesOfFreedom(2.0, 7.0, 1.0, 63.0), 9.0 / (4.0 / 7.0 + 1.0 / 63.0), 1e-12);
  // One estimate alone keeps its own; equal estimates with equal degrees add them.
  EXPECT_DOUBLE_EQ(welchDegreesOfFreedom(3.0, 7.0, 0.0, 63.0), 7.0);
  EXPECT_DOUBLE_EQ(welchDegreesOfFreedom(1.0, 10.0, 1.0, 10.0), 20.0);
  EXPECT_DOUBLE_EQ(welchDegreesOfFreedom(0.0, 7.0, 0.0, 63.0), 70.0);
  EXPECT_THROW(welchDegreesOfFreedom(-1.0, 7.0, 1.0, 63.0), PathwayError);
  EXPECT_THROW(welchDegreesOfFreedom(1.0, 0.0, 1.0, 63.0), PathwayError);
}

}  // namespace
}  // namespace pathway
