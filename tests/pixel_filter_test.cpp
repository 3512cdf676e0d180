// Stage 1's filter profiles against their formulas, and the PixelFilter that scales them.
#include "film/pixel_filter.h"

#include <gtest/gtest.h>

#include <cmath>

#include "core/error.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

// Midpoint rule over [-r, r]; exact enough (1e-6) for these piecewise-smooth profiles.
double integrate(const PixelFilter& filter) {
  const int n = 200000;
  const double r = filter.radius(), h = 2.0 * r / n;
  double sum = 0.0;
  for (int i = 0; i < n; ++i) sum += filter.evaluate1D(static_cast<float>(-r + (i + 0.5) * h));
  return sum * h;
}

const FilterProfiles& reference() {
  return test::stage1UnderTest().profiles;
}

TEST(PixelFilter, ProfilesIntegrateToTheirAnalyticValues) {
  PATHWAY_REQUIRE_REFERENCE();
  EXPECT_NEAR(integrate(PixelFilter(FilterType::Box, 0.5f, reference())), 1.0, 1e-4);
  EXPECT_NEAR(integrate(PixelFilter(FilterType::Tent, 1.0f, reference())), 1.0, 1e-4);
  // Mitchell-Netravali integrates to 1 for every B, C.
  EXPECT_NEAR(integrate(PixelFilter(FilterType::MitchellNetravali, 2.0f, reference())), 1.0, 1e-4);
  // Gaussian, σ = 0.5, cut at 3σ: σ·sqrt(2π)·erf(3/sqrt(2)).
  const double sigma = 0.5;
  EXPECT_NEAR(integrate(PixelFilter(FilterType::Gaussian, 1.5f, reference())),
              sigma * std::sqrt(2.0 * M_PI) * std::erf(3.0 / std::sqrt(2.0)), 1e-4);
}

TEST(PixelFilter, ProfilesMatchTheirFormulasPointwise) {
  PATHWAY_REQUIRE_REFERENCE();
  const FilterProfiles& f = reference();
  for (float x = -3.0f; x <= 3.0f; x += 0.01f) {
    const float a = std::fabs(x);
    EXPECT_FLOAT_EQ(f.box(x), a <= 0.5f ? 1.0f : 0.0f) << x;
    EXPECT_NEAR(f.tent(x), std::fmax(0.0f, 1.0f - a), 1e-6) << x;
    const float mn = a < 1    ? (7 * a * a * a - 12 * a * a + 16.0f / 3) / 6
                     : a <= 2 ? (-7.0f / 3 * a * a * a + 12 * a * a - 20 * a + 32.0f / 3) / 6
                              : 0.0f;
    EXPECT_NEAR(f.mitchellNetravali(x), mn, 1e-6) << x;
    const float g = a <= 1.5f ? std::exp(-x * x / (2 * 0.25f)) : 0.0f;
    EXPECT_NEAR(f.gaussian(x, 0.5f), g, 1e-6) << x;
  }
}

TEST(PixelFilter, MitchellNetravaliHasItsNegativeLobeMinimumAt10Over7) {
  PATHWAY_REQUIRE_REFERENCE();
  const FilterProfiles& f = reference();
  // d/dx of the outer cubic vanishes at |x| = 10/7, where f = -16/441 = -0.036281
  // (docs/stability.md derives it).
  EXPECT_NEAR(f.mitchellNetravali(10.0f / 7.0f), -0.036281, 1e-5);
  EXPECT_LT(f.mitchellNetravali(10.0f / 7.0f), f.mitchellNetravali(10.0f / 7.0f - 0.05f));
  EXPECT_LT(f.mitchellNetravali(10.0f / 7.0f), f.mitchellNetravali(10.0f / 7.0f + 0.05f));
  EXPECT_NEAR(f.mitchellNetravali(0.0f), 16.0f / 18.0f, 1e-6);
}

TEST(PixelFilter, SupportEndsAtTheRadiusAndScalesWithIt) {
  PATHWAY_REQUIRE_REFERENCE();
  for (FilterType type :
       {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali, FilterType::Gaussian}) {
    for (float radius : {0.5f, 1.0f, 2.5f}) {
      const PixelFilter filter(type, radius, reference());
      EXPECT_EQ(filter.evaluate1D(radius * 1.001f), 0.0f) << filterTypeName(type);
      EXPECT_EQ(filter.evaluate(0.0f, -radius * 1.5f), 0.0f) << filterTypeName(type);
      EXPECT_GT(filter.evaluate(0.0f, 0.0f), 0.0f) << filterTypeName(type);
      // Scaling the support scales the profile's argument: f_r(x) = f(x · natural / r).
      const PixelFilter natural(type, naturalFilterRadius(type), reference());
      const float x = 0.3f * radius;
      EXPECT_NEAR(filter.evaluate1D(x), natural.evaluate1D(x * naturalFilterRadius(type) / radius),
                  1e-6);
    }
  }
}

TEST(PixelFilter, RejectsBadNamesAndRadii) {
  EXPECT_EQ(parseFilterType("mitchell"), FilterType::MitchellNetravali);
  try {
    parseFilterType("lanczos");
    FAIL() << "no exception";
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find("lanczos"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("gaussian"), std::string::npos);
  }
  const FilterProfiles none;
  EXPECT_THROW(PixelFilter(FilterType::Box, 0.0f, none), PathwayError);
  EXPECT_THROW(PixelFilter(FilterType::Box, NAN, none), PathwayError);
  EXPECT_THROW(PixelFilter(FilterType::Box, 100.0f, none), PathwayError);
}

}  // namespace
}  // namespace pathway
