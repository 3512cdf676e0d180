// Picks one of the scene's emissive triangles for next-event estimation (stage 5), with
// probability proportional to its area or to its power. Choosing the point on the triangle is
// the stage's own work.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "sampling/discrete_distribution.h"
#include "scene/emitters.h"
#include "scene/scene.h"
#include "scene/surface_hit.h"

namespace pathway {

// A point picked on the emitters, and the density with which it was picked.
struct LightSample {
  Vec3 position;
  Vec3 normal;  // the emitter's front-face normal
  const EmissiveTriangle* emitter = nullptr;
  float pdfArea = 0.0f;  // density of this point per unit area, over all emitters
};

// How the picker weights the emitters (stage 5's light-pick parameter lists them in this order).
enum class EmitterWeighting { Area, Power };

class EmitterPicker {
 public:
  struct Pick {
    const EmissiveTriangle* emitter;
    float probability;  // of picking this triangle
  };

  EmitterPicker(const Scene& scene, EmitterWeighting weighting);

  bool empty() const { return distribution_.empty(); }  // no emitter can emit power
  // The triangle whose share of the total weight holds u in [0, 1). Not to be called when empty.
  Pick pick(float u) const {
    const size_t index = distribution_.sample(u);
    return {&emitters_[index], distribution_.probability(index)};
  }
  // The triangle `hit` lies on as pick() would choose it, with the same probability ({nullptr,
  // 0} where it emits nothing): what multiple importance sampling needs to weigh light a bounce
  // ray found against the light sample that could have found it (density per area:
  // probability / emitter->area).
  Pick pickOf(const SurfaceHit& hit) const;

 private:
  static uint64_t key(uint32_t mesh, uint32_t triangle) {
    return (uint64_t(mesh) << 32) | triangle;
  }

  std::vector<EmissiveTriangle> emitters_;
  DiscreteDistribution distribution_;
  std::unordered_map<uint64_t, size_t> indexOf_;  // by key(mesh, triangle)
};

}  // namespace pathway
