#include "scene/emitters.h"

#include <cmath>

namespace pathway {

std::vector<EmissiveTriangle> collectEmissiveTriangles(const Scene& scene) {
  std::vector<EmissiveTriangle> emitters;
  for (uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    const Material& material = scene.materials[mesh.material];
    if (!material.isEmissive() || !isFinite(material.emission)) continue;
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
      const glm::uvec3 tri = mesh.triangles[t];
      EmissiveTriangle e;
      e.p0 = mesh.positions[tri.x];
      e.p1 = mesh.positions[tri.y];
      e.p2 = mesh.positions[tri.z];
      const Vec3 cross = glm::cross(e.p1 - e.p0, e.p2 - e.p0);
      const float twiceArea = glm::length(cross);
      if (!(twiceArea > 0.0f) || !std::isfinite(twiceArea)) continue;
      e.normal = cross / twiceArea;
      e.area = 0.5f * twiceArea;
      e.emission = material.emission;
      e.doubleSided = material.doubleSided;
      e.mesh = m;
      e.triangle = t;
      emitters.push_back(e);
    }
  }
  return emitters;
}

}  // namespace pathway
