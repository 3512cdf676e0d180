#include "viewer/loaded_scene.h"

#include "scene/gltf_loader.h"

namespace pathway {

std::shared_ptr<const LoadedScene> LoadedScene::load(const std::string& path) {
  auto loaded = std::make_shared<LoadedScene>();
  loaded->scene = loadScene(path);
  loaded->tracer = std::make_unique<RayTracer>(loaded->scene);
  return loaded;
}

}  // namespace pathway
