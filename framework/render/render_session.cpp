#include "render/render_session.h"

#include <cstdio>

#include "core/error.h"
#include "io/partial_film.h"

namespace pathway {
namespace {

// The recipe with every parameter present: the defaults when none were given.
RenderRecipe completed(const IntegratorInfo& info, RenderRecipe recipe) {
  if (recipe.params.specs().empty()) {
    recipe.params = ParamValues(info.params);
    return recipe;
  }
  bool same = recipe.params.specs().size() == info.params.size();
  for (size_t i = 0; same && i < info.params.size(); ++i)
    same = recipe.params.specs()[i].name == info.params[i].name;
  if (!same)
    throw PathwayError("internal: the parameter values given are not those of " + info.name);
  return recipe;
}

ImageMetadata renderMetadata(const std::string& scenePath, const std::string& sceneHash, int stage,
                             const RenderRecipe& recipe, const RenderStats& stats,
                             size_t unresolvedPixels, const std::vector<TodoRecord>& todos) {
  std::string todoSites;
  for (const TodoRecord& todo : todos)
    todoSites += (todoSites.empty() ? "" : "; ") + todo.file + ":" + std::to_string(todo.line);
  const RenderSettings& s = recipe.settings;
  const RayCounters& c = stats.counters;
  const double seconds = stats.seconds;
  return {
      {"pathway:scene", scenePath},
      {"pathway:sceneHash", sceneHash},
      {"pathway:integrator", recipe.integrator},
      {"pathway:stage", std::to_string(stage)},
      {"pathway:params", recipe.params.describe()},
      {"pathway:earlierStages", earlierStagesName(recipe.earlierStages)},
      {"pathway:spp", std::to_string(stats.samplesPerPixel)},
      {kSampleRangeKey, std::to_string(s.firstSample()) + ":" +
                            std::to_string(s.firstSample() + stats.samplesPerPixel)},
      {kSampleRangeOfKey, std::to_string(s.samplesPerPixel)},
      {"pathway:sampler", samplerTypeName(s.sampler)},
      {"pathway:seed", std::to_string(s.seed)},
      {"pathway:filter", filterTypeName(s.filter)},
      {"pathway:filterRadius", std::to_string(s.filterRadiusPixels())},
      {"pathway:primaryRays", std::to_string(c.primary)},
      {"pathway:secondaryRays", std::to_string(c.secondary)},
      {"pathway:shadowRays", std::to_string(c.shadow)},
      {"pathway:samples", std::to_string(c.samples)},
      {"pathway:invalidSamples", std::to_string(c.invalidSamples)},
      {"pathway:unresolvedPixels", std::to_string(unresolvedPixels)},
      {"pathway:seconds", std::to_string(seconds)},
      {"pathway:raysPerSecond", std::to_string(seconds > 0 ? c.totalRays() / seconds : 0.0)},
      {"pathway:todos", std::to_string(todos.size())},
      {"pathway:todoSites", todoSites},
  };
}

}  // namespace

RenderSession::RenderSession(const RayTracer& tracer, const Camera& camera,
                             const RenderRecipe& recipe)
    : tracer_(tracer),
      info_(findIntegrator(recipe.integrator)),
      recipe_(completed(info_, recipe)),
      kit_(info_.kit(recipe.earlierStages)),
      camera_(camera) {
  char hash[17];
  std::snprintf(hash, sizeof hash, "%016llx", static_cast<unsigned long long>(tracer.sceneHash()));
  sceneHash_ = hash;
  recipe_.settings.check();
  integratorObject_ = info_.create({recipe_.params, kit_, tracer.scene()});
  renderer_ = std::make_unique<Renderer>(tracer, camera_, *integratorObject_, kit_.stage1(),
                                         recipe_.settings);
}

RenderSession::~RenderSession() = default;

RenderResult RenderSession::develop(std::vector<TodoRecord> todos) {
  RenderResult result;
  const Film& film = renderer_->film();
  film.developAll(result.images.color, result.images.variance, result.images.weight,
                  &result.unresolvedPixels);
  result.stats = renderer_->stats();
  result.todos = std::move(todos);
  result.metadata = renderMetadata(tracer_.scene().sourcePath, sceneHash_, info_.stage, recipe_,
                                   result.stats, result.unresolvedPixels, result.todos);
  return result;
}

RenderResult runRender(const RayTracer& tracer, const Camera& camera, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass) {
  clearTodosHit();  // from here on, every TODO that runs belongs to this render
  RenderSession session(tracer, camera, recipe);
  session.renderer().renderAll(onPass);
  return session.develop(todosHit());
}

RenderResult runRender(const RayTracer& tracer, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass) {
  const Camera camera(tracer.scene(), recipe.settings.width, recipe.settings.height);
  return runRender(tracer, camera, recipe, onPass);
}

}  // namespace pathway
