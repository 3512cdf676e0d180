// The diagnosis's robust fit against what the formulas give: exact data is fitted exactly, one far
// outlier barely moves Huber's fit where it drags least squares, and degenerate columns give no
// fit.
#include "grade/robust_fit.h"

#include <gtest/gtest.h>

namespace pathway {
namespace {

TEST(RobustFit, HuberLossIsSquareInsideTheLimitAndALineOutside) {
  EXPECT_DOUBLE_EQ(huberLoss(2.0), 4.0);
  EXPECT_DOUBLE_EQ(huberLoss(-3.0), 9.0);
  // 2·3·|r| − 9: continuous at the limit, slope 6 beyond it.
  EXPECT_DOUBLE_EQ(huberLoss(10.0), 51.0);
  EXPECT_DOUBLE_EQ(totalHuberLoss({1.0, -2.0, 10.0}), 1.0 + 4.0 + 51.0);
}

TEST(RobustFit, ExactDataIsFittedExactly) {
  // y = 2·a − 0.5·b on 12 values: the fit finds both and explains all of y's loss.
  Vector a, b, y;
  for (int i = 0; i < 12; ++i) {
    a.push_back(1.0 + 0.1 * i);
    b.push_back(i % 3 == 0 ? 1.0 : -0.5 * i);
    y.push_back(2.0 * a.back() - 0.5 * b.back());
  }
  const Fit fit = robustFit(y, {a, b}, totalHuberLoss(y));
  ASSERT_EQ(fit.coefficients.size(), 2u);
  EXPECT_NEAR(fit.coefficients[0], 2.0, 1e-9);
  EXPECT_NEAR(fit.coefficients[1], -0.5, 1e-9);
  EXPECT_NEAR(fit.explained, totalHuberLoss(y), 1e-9);
}

TEST(RobustFit, OneFarOutlierBarelyMovesTheFit) {
  // y = 1 + alternating ±0.5 noise on 40 values, one of them 100: the mean (least squares) moves
  // by 99/40 = 2.5; Huber's weight 3/|r| leaves the outlier about 3 of pull: (3 - 0) / 40 ≈ 0.08.
  Vector ones(40, 1.0), y;
  for (int i = 0; i < 40; ++i) y.push_back(1.0 + (i % 2 ? 0.5 : -0.5));
  y[7] = 100.0;
  const Fit fit = robustFit(y, {ones}, totalHuberLoss(y));
  ASSERT_EQ(fit.coefficients.size(), 1u);
  EXPECT_NEAR(fit.coefficients[0], 1.0, 0.1);
  double mean = 0.0;
  for (double value : y) mean += value / 40.0;
  EXPECT_GT(mean - 1.0, 2.0);  // what least squares would have given
}

TEST(RobustFit, DegenerateColumnsGiveNoFit) {
  const Vector a = {1.0, 2.0, 3.0}, twice = {2.0, 4.0, 6.0}, y = {1.0, 1.0, 1.0};
  EXPECT_TRUE(robustFit(y, {a, twice}, totalHuberLoss(y)).coefficients.empty());
}

}  // namespace
}  // namespace pathway
