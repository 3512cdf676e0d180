#include "engine/render_session.h"

#include <cstdio>

#include "core/error.h"

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

RenderMetadata renderMetadata(const std::string& scenePath, const std::string& sceneHash, int stage,
                              const RenderRecipe& recipe, const RenderStats& stats,
                              size_t unresolvedPixels, const std::vector<TodoRecord>& todos) {
  const RenderSettings& s = recipe.settings;
  const RayCounters& c = stats.counters;
  RenderMetadata m;
  m.scene = scenePath;
  m.sceneHash = sceneHash;
  m.integrator = recipe.integrator;
  m.stage = stage;
  m.params = recipe.params.describe();
  m.earlierStages = earlierStagesName(recipe.earlierStages);
  m.sampler = s.sampler;
  m.seed = s.seed;
  m.filter = s.filter;
  m.filterRadius = s.filterRadiusPixels();
  m.spp = stats.samplesPerPixel;
  m.sampleBegin = s.firstSample();
  m.sampleEnd = s.firstSample() + stats.samplesPerPixel;
  m.samplesOfWhole = s.samplesPerPixel;
  m.primaryRays = c.primary;
  m.secondaryRays = c.secondary;
  m.shadowRays = c.shadow;
  m.samples = c.samples;
  m.invalidSamples = c.invalidSamples;
  m.unresolvedPixels = unresolvedPixels;
  m.timing = RenderTiming{stats.seconds, stats.seconds > 0 ? c.totalRays() / stats.seconds : 0.0};
  m.todos = static_cast<int>(todos.size());
  for (const TodoRecord& todo : todos)
    m.todoSites.push_back(todo.file + ":" + std::to_string(todo.line));
  return m;
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
  {
    const CurrentTodoLog logged(&constructionTodos_);  // a stage's constructor may run a TODO
    integratorObject_ = info_.create({recipe_.params, kit_, tracer.scene()});
  }
  renderer_ = std::make_unique<Renderer>(tracer, camera_, *integratorObject_, kit_.stage1(),
                                         recipe_.settings);
}

RenderSession::~RenderSession() = default;

std::vector<TodoRecord> RenderSession::todos() const {
  std::vector<TodoRecord> all = constructionTodos_.records();
  for (const TodoRecord& todo : renderer_->todos().records()) {
    bool known = false;
    for (const TodoRecord& seen : all)
      known = known || (seen.file == todo.file && seen.line == todo.line);
    if (!known) all.push_back(todo);
  }
  return all;
}

RenderResult RenderSession::develop() {
  RenderResult result;
  const Film& film = renderer_->film();
  film.developAll(result.images.color, result.images.variance, result.images.weight,
                  &result.unresolvedPixels);
  result.stats = renderer_->stats();
  result.todos = todos();
  result.metadata = renderMetadata(tracer_.scene().sourcePath, sceneHash_, info_.stage, recipe_,
                                   result.stats, result.unresolvedPixels, result.todos);
  return result;
}

RenderResult runRender(const RayTracer& tracer, const Camera& camera, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass) {
  RenderSession session(tracer, camera, recipe);
  session.renderer().renderAll(onPass);
  return session.develop();
}

RenderResult runRender(const RayTracer& tracer, const RenderRecipe& recipe,
                       const std::function<void(const RenderStats&)>& onPass) {
  const Camera camera(tracer.scene(), recipe.settings.width, recipe.settings.height);
  return runRender(tracer, camera, recipe, onPass);
}

}  // namespace pathway
