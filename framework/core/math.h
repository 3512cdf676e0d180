// Vector types (GLM), rays, and small geometric helpers shared by every layer.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/glm.hpp>
#include <limits>

namespace pathway {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Color = glm::vec3;  // linear RGB radiance or reflectance

constexpr float kPi = 3.14159265358979323846f;
constexpr float kInvPi = 1.0f / kPi;
constexpr float kInfinity = std::numeric_limits<float>::infinity();

struct Ray {
  Vec3 origin;
  Vec3 direction;          // need not be unit length; distances are in units of |direction|
  float tMax = kInfinity;  // the segment is (0, tMax]
};

inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

inline float maxComponent(const Vec3& v) {
  return std::fmax(v.x, std::fmax(v.y, v.z));
}

// An orthonormal basis (tangent, bitangent, normal) around a unit normal, without branches
// that flip at the poles (Duff et al. 2017, "Building an Orthonormal Basis, Revisited").
struct Frame {
  Vec3 tangent, bitangent, normal;

  explicit Frame(const Vec3& n) : normal(n) {
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    tangent = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    bitangent = Vec3(b, sign + n.y * n.y * a, -n.y);
  }
  Vec3 toWorld(const Vec3& local) const {
    return local.x * tangent + local.y * bitangent + local.z * normal;
  }
};

// Moves a surface point off its surface along the geometric normal `n` (pointing to the side the
// new ray leaves from) by a few float ULPs of its own coordinates, so that the new ray cannot hit
// the surface it starts on at any scale or distance from the origin.
// Wächter & Binder, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems.
// Inline: it runs for every secondary ray.
inline Vec3 offsetRayOrigin(const Vec3& p, const Vec3& n) {
  // Near the origin ULP steps are tiny, so a fixed absolute offset takes over there.
  constexpr float kOrigin = 1.0f / 32.0f;
  constexpr float kFloatScale = 1.0f / 65536.0f;
  constexpr float kIntScale = 256.0f;
  Vec3 result;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::fabs(p[axis]) < kOrigin) {
      result[axis] = p[axis] + kFloatScale * n[axis];
      continue;
    }
    // Step the float's bit pattern by whole ULPs, away from zero when n points away from it.
    // Unsigned arithmetic: the same bits as the paper's signed version, without its overflow.
    const auto ulps = static_cast<int32_t>(kIntScale * n[axis]);
    uint32_t bits;
    std::memcpy(&bits, &p[axis], sizeof bits);
    bits += static_cast<uint32_t>(p[axis] < 0 ? -ulps : ulps);
    std::memcpy(&result[axis], &bits, sizeof bits);
  }
  return result;
}

}  // namespace pathway
