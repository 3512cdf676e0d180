// The stage's integrator as the viewer runs it: wrapped, to do two things the renderer does not.
//
// Rays per pixel, for the heatmap: each camera sample's rays are the difference of the tile's ray
// counters before and after the real Li(), added to the pixel the camera ray came from. Li() only
// gets the camera ray, so the pixel is found by inverting the pinhole projection
// (Camera::generateRay) for a camera built from the same pose.
//
// Cancelling within a tile: the renderer looks at its cancel flag only between tiles, and a tile
// at many samples per pass can take minutes. When the flag is set, the next Li() throws
// PassCancelled; TBB carries it out of Renderer::renderPass before the merge, so the film is
// untouched, and the worker drops that renderer anyway. (A cancel check per pixel inside the
// renderer would make this unnecessary.)
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>

#include "render/integrator.h"
#include "viewer/orbit_camera.h"

namespace pathway {

struct PassCancelled {};

class ViewerIntegrator : public Integrator {
 public:
  ViewerIntegrator(const Integrator& inner, const CameraPose& pose, int width, int height,
                   const std::atomic<bool>* cancel);

  Color Li(const Ray& cameraRay, SampleStream& samples, RenderContext& context) const override;

  // Rays traced for the samples of pixel (x, y) so far.
  uint64_t rays(int x, int y) const {
    return rays_[static_cast<size_t>(y) * width_ + x].load(std::memory_order_relaxed);
  }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const Integrator& inner_;
  const std::atomic<bool>* cancel_;
  Vec3 forward_, right_, up_;
  float halfWidth_, halfHeight_;
  int width_, height_;
  // Tiles run in parallel and a sample can land on a tile edge after rounding: relaxed atomics.
  std::unique_ptr<std::atomic<uint64_t>[]> rays_;
};

}  // namespace pathway
