// A scene and its BVH, loaded once and shared: the UI keeps the current one, the render worker
// keeps the one it is rendering until its lanes switch to a new one. The tracer points into the
// scene, so the pair lives in one heap object that never moves.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "scene/gltf_loader.h"
#include "scene/ray_tracer.h"
#include "scene/scene.h"

namespace pathway {

struct LoadedScene {
  Scene scene;
  std::unique_ptr<RayTracer> tracer;
  uint64_t contentHash = 0;  // Scene::contentHash(), once: it tells two loads of a file apart

  // Throws PathwayError naming the file and the problem.
  static std::shared_ptr<const LoadedScene> load(const std::string& path,
                                                 const SceneLoadOptions& options = {});
};

}  // namespace pathway
