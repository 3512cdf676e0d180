#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "core/stable_hash.h"

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

uint64_t Scene::contentHash() const {
  StableHash hash;
  for (const Mesh& mesh : meshes) {
    hash.add(mesh.positions.data(), mesh.positions.size());
    hash.add(mesh.triangles.data(), mesh.triangles.size());
    hash.add(mesh.texcoords.data(), mesh.texcoords.size());
    hash.add(mesh.material);
  }
  for (const Material& material : materials) {
    hash.add(material.baseColor);
    hash.add(material.baseColorTexture);
    hash.add(material.emission);
    hash.add(material.doubleSided);
  }
  for (const Texture& texture : textures) hash.add(texture.texels.data(), texture.texels.size());
  if (camera) {
    hash.add(camera->cameraToWorld);
    hash.add(camera->yfov);
    hash.add(camera->aspectRatio.value_or(0.0f));
  }
  hash.add(background);
  return hash.value();
}

size_t Scene::triangleCount() const {
  size_t count = 0;
  for (const Mesh& mesh : meshes) count += mesh.triangleCount();
  return count;
}

int Scene::imageHeight(int width) const {
  const float aspect = camera && camera->aspectRatio ? *camera->aspectRatio : 1.0f;
  return std::max(1, static_cast<int>(std::lround(width / aspect)));
}

}  // namespace pathway
