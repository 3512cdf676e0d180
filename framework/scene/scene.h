// The scene model: exactly what the five stages use and nothing more.
// Triangle meshes in world space (shared with Embree, never copied), Lambertian albedo
// (factor x texture), emission (one-sided unless double-sided), a camera, a constant background.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/math.h"
#include "scene/padded_allocator.h"

namespace pathway {

// Linear-RGB texels, row 0 at the top (as glTF images are stored).
struct Texture {
  int width = 0;
  int height = 0;
  std::vector<Color> texels;

  // Bilinear lookup with repeat wrapping; uv as in glTF (v = 0 at the top row).
  Color lookup(Vec2 uv) const;
};

struct Material {
  std::string name;
  Color baseColor{1.0f};      // glTF baseColorFactor (rgb)
  int baseColorTexture = -1;  // index into Scene::textures, sampled with the mesh's TEXCOORD_0
  Color emission{0.0f};       // emissiveFactor x KHR_materials_emissive_strength
  bool doubleSided = false;   // emits from both faces when true, from the front face otherwise

  bool isEmissive() const { return maxComponent(emission) > 0.0f; }
};

struct Mesh {
  std::string name;
  // World-space positions. The allocator leaves the slack Embree reads past the last vertex.
  std::vector<Vec3, PaddedAllocator<Vec3>> positions;
  std::vector<glm::uvec3> triangles;  // counter-clockwise seen from the front face
  std::vector<Vec2> texcoords;        // TEXCOORD_0, one per vertex; empty when not needed
  uint32_t material = 0;              // index into Scene::materials

  size_t triangleCount() const { return triangles.size(); }
};

struct Bounds {
  Vec3 lower{kInfinity};
  Vec3 upper{-kInfinity};

  void extend(const Vec3& p) {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  bool isEmpty() const { return lower.x > upper.x; }
  Vec3 center() const { return 0.5f * (lower + upper); }
  Vec3 extent() const { return upper - lower; }
};

// A glTF perspective camera placed in the world. The camera looks down its local -Z axis with +Y
// up.
struct CameraPlacement {
  glm::mat4 cameraToWorld{1.0f};
  float yfov = 0.0f;                 // vertical field of view, radians
  std::optional<float> aspectRatio;  // width / height, when the file gives it
};

struct Scene {
  std::string sourcePath;
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::optional<CameraPlacement> camera;  // absent: the renderer frames the bounds
  Color background{0.0f};                 // radiance of rays that leave the scene
  Bounds bounds;
  std::vector<std::string> warnings;  // one per unsupported feature, already printed

  size_t triangleCount() const;
  // The image height that goes with `width`: from the camera's aspect ratio, square without one.
  int imageHeight(int width) const;
  // A hash of everything that changes an image (geometry, materials, textures, camera,
  // background), not of the file's formatting: renders record it so that images made from
  // different scenes are never compared or merged.
  uint64_t contentHash() const;
};

}  // namespace pathway
