// Internals shared by the glTF loader's source files (gltf_loader.cpp, gltf_geometry.cpp,
// gltf_materials.cpp). Not part of the framework's interface: include scene/gltf_loader.h instead.
#pragma once

#include <tiny_gltf.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace pathway::gltf {

// The problems found in one file. Errors throw at once; warnings are kept, one per feature, and
// printed by the loader only when the whole file has loaded.
class Diagnostics {
 public:
  explicit Diagnostics(std::string file) : file_(std::move(file)) {}

  // Throws PathwayError("<file>: <problem>").
  [[noreturn]] void fail(const std::string& problem) const;
  // Fails unless 0 <= index < count. `reference` says who refers to what, e.g. "node 2 refers to
  // mesh", and leads the message.
  void checkIndex(int index, size_t count, const std::string& reference) const;
  // Keeps "<file>: <message>" unless a warning about `feature` was kept already.
  void warnOnce(const std::string& feature, const std::string& message);

  const std::vector<std::string>& warnings() const { return warnings_; }

 private:
  std::string file_;
  std::set<std::string> warnedFeatures_;
  std::vector<std::string> warnings_;
};

// Names a glTF object in messages: `mesh "box"`, or `mesh 2` when it has no name.
std::string describe(const std::string& kind, int index, const std::string& name);

// Converts glTF materials and their textures on first use, so that the scene holds only what its
// meshes refer to (and warns only about features of materials that are actually used).
class MaterialTable {
 public:
  MaterialTable(const tinygltf::Model& model, Scene& scene, Diagnostics& diagnostics)
      : model_(model), scene_(scene), diagnostics_(diagnostics) {}

  // The index into Scene::materials for a glTF material index (-1: the default white material).
  uint32_t sceneMaterial(int gltfMaterial);

 private:
  Material convertMaterial(int gltfMaterial);
  int baseColorTexture(const tinygltf::TextureInfo& info, const std::string& material);
  int sceneTexture(int gltfTexture, const std::string& material);

  const tinygltf::Model& model_;
  Scene& scene_;
  Diagnostics& diagnostics_;
  std::map<int, uint32_t> materials_;  // glTF material index -> scene material index
  std::map<int, int> textures_;        // glTF texture index -> scene texture index
};

// Appends one instance of glTF mesh `meshIndex`, placed by `toWorld`: one scene Mesh per
// TRIANGLES primitive that has triangles.
void addMeshInstance(const tinygltf::Model& model, int meshIndex, const glm::dmat4& toWorld,
                     MaterialTable& materials, Scene& scene, Diagnostics& diagnostics);

}  // namespace pathway::gltf
