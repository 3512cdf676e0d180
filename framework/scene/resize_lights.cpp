#include "scene/resize_lights.h"

#include <cmath>
#include <string>

#include "core/error.h"

namespace pathway {

void resizeLights(Scene& scene, float factor) {
  if (!(factor > 0.0f) || !std::isfinite(factor))
    throw PathwayError("a light's scale must be positive and finite, got " +
                       std::to_string(factor));
  if (factor == 1.0f) return;
  for (Mesh& mesh : scene.meshes) {
    if (!scene.materials[mesh.material].isEmissive()) continue;
    Bounds bounds;
    for (const Vec3& position : mesh.positions) bounds.extend(position);
    const Vec3 centre = bounds.center();
    for (Vec3& position : mesh.positions) position = centre + factor * (position - centre);
  }
  // Radiance × area is the power: the area grew by factor², so the radiance shrinks by as much.
  for (Material& material : scene.materials)
    if (material.isEmissive()) material.emission /= factor * factor;
}

}  // namespace pathway
