#include "render/render_job.h"

#include <sstream>

namespace pathway {
ImageMetadata renderMetadata(const std::string& scenePath, const std::string& integrator,
                             const std::string& params, const RenderSettings& s,
                             const RenderStats& stats, size_t unresolvedPixels, size_t todoCount) {
  const RayCounters& c = stats.counters;
  const double seconds = stats.seconds;
  return {
      {"pathway:scene", scenePath},
      {"pathway:integrator", integrator},
      {"pathway:params", params},
      {"pathway:spp", std::to_string(stats.samplesPerPixel)},
      {"pathway:sampler", samplerTypeName(s.sampler)},
      {"pathway:seed", std::to_string(s.seed)},
      {"pathway:filter", filterTypeName(s.filter)},
      {"pathway:filterRadius",
       std::to_string(s.filterRadius > 0 ? s.filterRadius : naturalFilterRadius(s.filter))},
      {"pathway:primaryRays", std::to_string(c.primary)},
      {"pathway:secondaryRays", std::to_string(c.secondary)},
      {"pathway:shadowRays", std::to_string(c.shadow)},
      {"pathway:samples", std::to_string(c.samples)},
      {"pathway:invalidSamples", std::to_string(c.invalidSamples)},
      {"pathway:unresolvedPixels", std::to_string(unresolvedPixels)},
      {"pathway:seconds", std::to_string(seconds)},
      {"pathway:raysPerSecond", std::to_string(seconds > 0 ? c.totalRays() / seconds : 0.0)},
      {"pathway:todos", std::to_string(todoCount)},
  };
}

RenderResult runRender(const Scene& scene, const RayTracer& tracer, const RenderRequest& request,
                       const std::function<void(const RenderStats&)>& onPass) {
  const IntegratorInfo& info = findIntegrator(request.integrator);
  const ParamValues params = resolveParams(info.name, info.params, request.params);
  const std::unique_ptr<Integrator> integrator = info.create(params, scene);
  const Camera camera(scene, request.settings.width, request.settings.height);
  Renderer renderer(tracer, camera, *integrator, filterFunctions(info.variant), request.settings);

  clearTodosHit();
  renderer.renderAll(onPass);

  RenderResult result;
  const Film& film = renderer.film();
  result.images.color = film.develop(&result.unresolvedPixels);
  result.images.variance = film.variance();
  result.images.weight = film.weights();
  result.stats = renderer.stats();
  result.todos = todosHit();
  std::ostringstream paramText;
  for (const ParamSpec& spec : info.params)
    paramText << (paramText.tellp() > 0 ? " " : "") << spec.name << "="
              << formatParamValue(spec, params.number(spec.name));
  result.metadata = renderMetadata(scene.sourcePath, info.name, paramText.str(), request.settings,
                                   result.stats, result.unresolvedPixels, result.todos.size());
  return result;
}

}  // namespace pathway
