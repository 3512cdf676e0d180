#include "render/emitter_picker.h"

namespace pathway {

EmitterPicker::EmitterPicker(const Scene& scene, EmitterWeighting weighting)
    : emitters_(collectEmissiveTriangles(scene)) {
  std::vector<double> weights;
  for (const EmissiveTriangle& e : emitters_) {
    const Color power = e.power();
    weights.push_back(weighting == EmitterWeighting::Power ? (power.x + power.y + power.z) / 3.0
                                                           : e.area);
  }
  distribution_ = DiscreteDistribution(weights);
}

}  // namespace pathway
