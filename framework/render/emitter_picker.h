// Picks one of the scene's emissive triangles for next-event estimation (stage 5), with
// probability proportional to its area or to its power. Choosing the point on the triangle is
// the stage's own work.
#pragma once

#include <vector>

#include "sampling/discrete_distribution.h"
#include "scene/emitters.h"
#include "scene/scene.h"

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

 private:
  std::vector<EmissiveTriangle> emitters_;
  DiscreteDistribution distribution_;
};

}  // namespace pathway
