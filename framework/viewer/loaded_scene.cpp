#include "viewer/loaded_scene.h"

namespace pathway {

std::shared_ptr<const LoadedScene> LoadedScene::load(const std::string& path,
                                                     const SceneLoadOptions& options) {
  auto loaded = std::make_shared<LoadedScene>();
  loaded->scene = loadScene(path, options);
  loaded->tracer = std::make_unique<RayTracer>(loaded->scene);
  loaded->contentHash = loaded->scene.contentHash();
  return loaded;
}

}  // namespace pathway
