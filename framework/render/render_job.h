// One render from start to finish, as the CLI, the tests and the benchmarks run it:
// integrator by name -> renderer -> developed images, counters and metadata.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/todo.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "render/renderer.h"
#include "scene/camera.h"
#include "scene/ray_tracer.h"

namespace pathway {

struct RenderRequest {
  std::string integrator = "stage1";
  std::map<std::string, std::string>
      params;  // name -> value text, checked against the declarations
  RenderSettings settings;
};

struct RenderResult {
  FilmImages images;
  RenderStats stats;
  size_t unresolvedPixels = 0;    // Σw ≈ 0 (negative filter lobes at low spp); written as 0
  std::vector<TodoRecord> todos;  // unfinished stage code that ran during this render
  ImageMetadata metadata;         // settings and counters, for the EXR header
};

// The "pathway:*" metadata every saved render carries: its settings and counters.
// `params` is the integrator's parameters as "name=value name=value".
ImageMetadata renderMetadata(const std::string& scenePath, const std::string& integrator,
                             const std::string& params, const RenderSettings& settings,
                             const RenderStats& stats, size_t unresolvedPixels, size_t todoCount);

// Validates the request (integrator name, parameters, settings) before any work is done, then
// renders every pass. `onPass` sees the progress after each pass.
RenderResult runRender(const Scene& scene, const RayTracer& tracer, const RenderRequest& request,
                       const std::function<void(const RenderStats&)>& onPass = {});

}  // namespace pathway
