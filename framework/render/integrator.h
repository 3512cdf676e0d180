// The integrator interface: one object per stage, asked for the radiance of one camera sample.
#pragma once

#include "core/math.h"
#include "core/ray_counters.h"
#include "sampling/sampler.h"
#include "scene/ray_tracer.h"

namespace pathway {

// What an integrator may use while it computes one sample.
struct RenderContext {
  const Scene& scene;
  const RayTracer& tracer;
  RayCounters& counters;  // the current tile's; pass it to every ray query
};

class Integrator {
 public:
  virtual ~Integrator() = default;

  // Radiance arriving at the camera along `cameraRay` (which the integrator traces itself, as a
  // RayKind::Primary ray). `samples` has used dimensions 0-1 for the pixel position; the
  // integrator takes its own random numbers from it, in a fixed order.
  virtual Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const = 0;
};

}  // namespace pathway
