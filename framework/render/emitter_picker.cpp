#include "render/emitter_picker.h"

#include "core/error.h"

namespace pathway {

EmitterPicker::EmitterPicker(const Scene& scene, const std::string& weighting)
    : emitters_(collectEmissiveTriangles(scene)) {
  if (weighting != "area" && weighting != "power")
    throw PathwayError("unknown emitter weighting '" + weighting + "' (area or power)");
  std::vector<double> weights;
  for (const EmissiveTriangle& e : emitters_) {
    const Color power = e.power();
    weights.push_back(weighting == "power" ? (power.x + power.y + power.z) / 3.0 : e.area);
  }
  distribution_ = DiscreteDistribution(weights);
}

}  // namespace pathway
