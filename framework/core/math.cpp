#include "core/math.h"

#include <cstdint>
#include <cstring>

namespace pathway {
namespace {

float intAsFloat(int32_t i) {
  float f;
  std::memcpy(&f, &i, sizeof f);
  return f;
}
int32_t floatAsInt(float f) {
  int32_t i;
  std::memcpy(&i, &f, sizeof i);
  return i;
}

}  // namespace

Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n) {
  // Near the origin ULP steps are tiny, so a fixed absolute offset takes over there.
  constexpr float kOrigin = 1.0f / 32.0f;
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;
  Vec3 result;
  for (int axis = 0; axis < 3; ++axis) {
    const int32_t ulps = static_cast<int32_t>(kIntScale * n[axis]);
    const float stepped = intAsFloat(floatAsInt(p[axis]) + (p[axis] < 0 ? -ulps : ulps));
    result[axis] = std::fabs(p[axis]) < kOrigin ? p[axis] + kFloatScale * n[axis] : stepped;
  }
  return result;
}

}  // namespace pathway
