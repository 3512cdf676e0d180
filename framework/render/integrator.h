// The integrator interface: one object per stage, asked for the radiance of one camera sample,
// and the context it traces its rays through.
#pragma once

#include <optional>

#include "core/math.h"
#include "core/ray_counters.h"
#include "sampling/sampler.h"
#include "scene/ray_tracer.h"

namespace pathway {

// What an integrator may use while it computes one sample. Every ray query counts itself (by
// kind) in the counters of the tile being rendered.
class RenderContext {
 public:
  RenderContext(const RayTracer& tracer, RayCounters& counters)
      : tracer_(tracer), counters_(counters) {}

  // The closest hit along `ray` in (0, tMax], or nothing. `kind`: Primary for the camera ray,
  // Secondary for rays that look for the next surface (AO, bounces).
  std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind) const {
    return tracer_.intersect(ray, kind, counters_);
  }
  // True when anything blocks `ray` in (0, tMax]. Cheaper than intersect(): it stops at the
  // first blocker. `kind`: Secondary for AO rays, Shadow for rays towards a light.
  bool occluded(const Ray& ray, RayKind kind) const {
    return tracer_.occluded(ray, kind, counters_);
  }

  // Radiance of rays that leave the scene.
  const Color& background() const { return tracer_.scene().background; }

  // For wavefront integrators (render/wavefront.h), which trace packets of rays: the tracer and
  // the counters its packet queries count in.
  const RayTracer& tracer() const { return tracer_; }
  RayCounters& counters() const { return counters_; }

 private:
  const RayTracer& tracer_;
  RayCounters& counters_;
};

class WavefrontIntegrator;

class Integrator {
 public:
  virtual ~Integrator() = default;

  // Radiance arriving at the camera along `cameraRay` (which the integrator traces itself, as a
  // RayKind::Primary ray). `samples` has used dimensions 0-1 for the pixel position; the
  // integrator takes its own random numbers from it, in a fixed order.
  virtual Color Li(const Ray& cameraRay, SampleStream& samples,
                   const RenderContext& context) const = 0;

  // A reference's wavefront version (render/wavefront.h) renders whole batches instead; the
  // renderer asks through this (no dynamic_cast: the type may live in a loaded library).
  virtual const WavefrontIntegrator* asWavefront() const { return nullptr; }
};

}  // namespace pathway
