#include "viewer/frame_metadata.h"

#include <sstream>

#include "film/pixel_filter.h"
#include "render/integrator_registry.h"
#include "sampling/sampler.h"

namespace pathway {
namespace {

std::string vec3Text(const Vec3& v) {
  std::ostringstream text;
  text << v.x << " " << v.y << " " << v.z;
  return text.str();
}

}  // namespace

ImageMetadata frameMetadata(const LaneFrame& frame) {
  const RenderSettings& s = frame.settings;
  const RayCounters& c = frame.stats.counters;
  std::ostringstream params;
  for (const auto& [name, value] : frame.params)
    params << (params.tellp() > 0 ? " " : "") << name << "=" << value;
  const double seconds = frame.stats.seconds;
  return {
      {"pathway:scene", frame.scenePath},
      {"pathway:integrator", frame.integrator},
      {"pathway:params", params.str()},
      {"pathway:spp", std::to_string(frame.stats.samplesPerPixel)},
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
      {"pathway:unresolvedPixels", std::to_string(frame.unresolvedPixels)},
      {"pathway:seconds", std::to_string(seconds)},
      {"pathway:raysPerSecond", std::to_string(seconds > 0 ? c.totalRays() / seconds : 0.0)},
      {"pathway:todos", std::to_string(frame.todos.size())},
      {"pathway:cameraPosition", vec3Text(frame.camera.position)},
      {"pathway:cameraLookAt", vec3Text(frame.camera.lookAt)},
      {"pathway:cameraUp", vec3Text(frame.camera.up)},
      {"pathway:cameraYfov", std::to_string(frame.camera.yfov)},
  };
}

}  // namespace pathway
