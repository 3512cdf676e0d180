// Small geometric helpers against their definitions.
#include "core/math.h"

#include <gtest/gtest.h>

#include <cmath>

#include "sampling/pcg32.h"

namespace pathway {
namespace {

TEST(MathFrame, IsOrthonormalAndRightHandedForEveryNormal) {
  Pcg32 rng(5);
  for (int i = 0; i < 10000; ++i) {
    // Random unit normals, plus the poles and the equator where naive bases break down.
    Vec3 n = i == 0   ? Vec3(0, 0, 1)
             : i == 1 ? Vec3(0, 0, -1)
             : i == 2 ? Vec3(1, 0, 0)
                      : glm::normalize(Vec3(rng.nextFloat() - 0.5f, rng.nextFloat() - 0.5f,
                                            rng.nextFloat() - 0.5f));
    const Frame frame(n);
    EXPECT_NEAR(glm::length(frame.tangent), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::length(frame.bitangent), 1.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(frame.tangent, frame.bitangent), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(frame.tangent, n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::dot(frame.bitangent, n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(glm::cross(frame.tangent, frame.bitangent), n), 0.0f, 1e-5f);
    EXPECT_NEAR(glm::distance(frame.toWorld(Vec3(0, 0, 1)), n), 0.0f, 1e-6f);
  }
}

TEST(MathOffset, MovesThePointToTheNormalsSideAtEveryScale) {
  const Vec3 up(0, 1, 0);
  for (float magnitude : {0.0f, 1e-3f, 0.5f, 1.0f, 1e3f, 1e4f, 1e6f}) {
    for (float sign : {1.0f, -1.0f}) {
      const Vec3 p(sign * magnitude, sign * magnitude, 0.25f);
      EXPECT_GT(offsetRayOrigin(p, up).y, p.y) << magnitude;
      EXPECT_LT(offsetRayOrigin(p, -up).y, p.y) << magnitude;
      // Only a few ULPs away: relative change below 1e-4 away from the origin.
      if (magnitude >= 1.0f) {
        EXPECT_LT(std::fabs(offsetRayOrigin(p, up).y - p.y), 1e-4f * magnitude) << magnitude;
      }
      EXPECT_EQ(offsetRayOrigin(p, up).x, p.x);  // no movement across the normal
    }
  }
}

}  // namespace
}  // namespace pathway
