#include "render/emitter_picker.h"

namespace pathway {

EmitterPicker::EmitterPicker(const Scene& scene, EmitterWeighting weighting)
    : emitters_(collectEmissiveTriangles(scene)) {
  std::vector<double> weights;
  for (const EmissiveTriangle& e : emitters_) {
    indexOf_[key(e.mesh, e.triangle)] = weights.size();
    const Color power = e.power();
    weights.push_back(weighting == EmitterWeighting::Power ? (power.x + power.y + power.z) / 3.0
                                                           : e.area);
  }
  distribution_ = DiscreteDistribution(weights);
}

EmitterPicker::Pick EmitterPicker::pickOf(const SurfaceHit& hit) const {
  const auto found = indexOf_.find(key(hit.mesh, hit.triangle));
  if (found == indexOf_.end() || distribution_.empty()) return {nullptr, 0.0f};
  return {&emitters_[found->second], distribution_.probability(found->second)};
}

}  // namespace pathway
