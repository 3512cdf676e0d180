// One render, built the same way by the CLI, the viewer, the tests and the benchmarks: a recipe
// (integrator by name, its parameter values, where its earlier stages come from, the settings)
// plus a scene and a camera become the integrator, its stage kit and a Renderer.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/todo.h"
#include "engine/render_settings.h"
#include "engine/renderer.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "scene/camera.h"
#include "scene/ray_tracer.h"

namespace pathway {

// Everything that decides an image besides the scene and the camera. Made by RecipeBuilder
// (engine/recipe_builder.h), which fills in the integrator's defaults and checks names.
struct RenderRecipe {
  std::string integrator = setting::kIntegrator;
  // The integrator's parameter values; left empty, every parameter takes its declared default.
  ParamValues params;
  EarlierStages earlierStages = EarlierStages::Own;
  RenderSettings settings;
};

struct RenderResult {
  FilmImages images;
  RenderStats stats;
  size_t unresolvedPixels = 0;    // Σw ≈ 0 (negative filter lobes at low spp); written as 0
  std::vector<TodoRecord> todos;  // unfinished stage code this render ran
  RenderMetadata metadata;        // settings and counters, for the EXR header
};

class RenderSession {
 public:
  // Checks the recipe (integrator name, parameters, settings) and builds everything; throws
  // PathwayError naming what it refuses before any rendering starts.
  RenderSession(const RayTracer& tracer, const Camera& camera, const RenderRecipe& recipe);
  ~RenderSession();
  RenderSession(const RenderSession&) = delete;  // the renderer refers to members: never moves
  RenderSession& operator=(const RenderSession&) = delete;

  Renderer& renderer() { return *renderer_; }
  const Renderer& renderer() const { return *renderer_; }
  const IntegratorInfo& integrator() const { return info_; }
  const RenderRecipe& recipe() const { return recipe_; }  // with every parameter value filled in

  // The unfinished stage code this render has run so far: while its integrator was built, and in
  // its tiles.
  std::vector<TodoRecord> todos() const;

  // The film so far, developed, with counters, the TODOs that ran and metadata (merges the
  // renderer's film).
  RenderResult develop();

 private:
  const RayTracer& tracer_;
  const IntegratorInfo& info_;
  RenderRecipe recipe_;
  StageKit kit_;
  TodoLog
      constructionTodos_;  // those the integrator's constructor ran (the renderer keeps the rest)
  std::unique_ptr<Integrator> integratorObject_;
  Camera camera_;
  std::string sceneHash_;  // of the scene's content, for the metadata
  std::unique_ptr<Renderer> renderer_;
};

// A whole render as the CLI and the tests run it: renders every pass (`onPass` sees the progress
// after each) and develops the result.
RenderResult runRender(const RayTracer& tracer, const Camera& camera, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass = {});
// The same with the scene's own camera (or the default framing) at the recipe's image size.
RenderResult runRender(const RayTracer& tracer, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass = {});

}  // namespace pathway
