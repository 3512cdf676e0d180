#include "scene/scene.h"

#include <cmath>

namespace pathway {

Color Texture::lookup(Vec2 uv) const {
  if (width <= 0 || height <= 0) return Color(1.0f);
  // Wrapping first keeps the integer texel coordinates below from overflowing for huge uv.
  uv -= glm::floor(uv);
  if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) uv = Vec2(0.0f);
  // Texel centres sit at half-integer coordinates.
  const float x = uv.x * width - 0.5f;
  const float y = uv.y * height - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float tx = x - fx, ty = y - fy;
  auto wrap = [](long i, int n) { return static_cast<int>(((i % n) + n) % n); };
  auto texel = [&](long ix, long iy) {
    return texels[static_cast<size_t>(wrap(iy, height)) * width + wrap(ix, width)];
  };
  const long ix = static_cast<long>(fx), iy = static_cast<long>(fy);
  return (1 - ty) * ((1 - tx) * texel(ix, iy) + tx * texel(ix + 1, iy)) +
         ty * ((1 - tx) * texel(ix, iy + 1) + tx * texel(ix + 1, iy + 1));
}

size_t Scene::triangleCount() const {
  size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.triangleCount();
  return count;
}

}  // namespace pathway
