// The scene's emissive triangles, gathered once so a stage can pick points on them (next-event
// estimation). Degenerate and zero-area emitters are left out: they can emit no power.
#pragma once

#include <vector>

#include "core/math.h"
#include "scene/scene.h"

namespace pathway {

struct EmissiveTriangle {
  Vec3 p0, p1, p2;
  Vec3 normal;  // unit, on the front (counter-clockwise) side
  float area = 0.0f;
  Color emission{0.0f};  // radiance leaving the front face (and the back, if doubleSided)
  bool doubleSided = false;
  uint32_t mesh = 0, triangle = 0;

  // Power: radiance x π x area, per emitting side.
  Color power() const { return emission * (kPi * area * (doubleSided ? 2.0f : 1.0f)); }
};

std::vector<EmissiveTriangle> collectEmissiveTriangles(const Scene& scene);

}  // namespace pathway
