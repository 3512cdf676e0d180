// The renderer: tiles x passes on TBB. Each pass adds `samplesPerPass` samples to every pixel;
// each tile splats into its own FilmBlock and the blocks are merged in a fixed order, so the image
// is bit-identical for any thread count. A render can be cancelled at any pixel.
//
// Merging touches every block and the whole film (about 100 bytes of sums per pixel), so it
// happens when the film is asked for, not after every pass: a render that only wants its final
// image merges once. A pass that may be cancelled is the exception (see renderPass).
#pragma once

#include <tbb/task_arena.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "core/ray_counters.h"
#include "core/todo.h"
#include "engine/render_settings.h"
#include "film/film.h"
#include "film/pixel_filter.h"
#include "render/integrator.h"
#include "render/stage_kit.h"
#include "sampling/sampler.h"
#include "scene/camera.h"

namespace pathway {

class WavefrontIntegrator;

struct RenderStats {
  RayCounters counters;
  double seconds = 0.0;          // wall time spent in passes
  uint32_t samplesPerPixel = 0;  // done so far (of the settings' sample range)
};

class Renderer {
 public:
  // Splats with stage 1's functions `stage1`; throws PathwayError for settings out of range.
  Renderer(const RayTracer& tracer, const Camera& camera, const Integrator& integrator,
           const Stage1Functions& stage1, const RenderSettings& settings);
  ~Renderer();

  // Renders the next pass. Returns false (and leaves the film as it was before the pass) when
  // `cancel` became true during it. With a `cancel` flag, earlier passes are merged first, so
  // that the blocks then hold only this pass and can be emptied if it is cancelled.
  bool renderPass(const std::atomic<bool>* cancel = nullptr);
  bool finished() const { return stats_.samplesPerPixel >= settings_.samplesToRender(); }

  // Renders the remaining passes, calling `onPass` after each. Returns false when cancelled.
  bool renderAll(const std::function<void(const RenderStats&)>& onPass = {},
                 const std::atomic<bool>* cancel = nullptr);

  // The sums of every finished pass: merges what the blocks still hold, so it changes the
  // renderer and must not run while a pass does.
  const Film& film();
  // Rays traced for the samples of each pixel so far (rows top to bottom), for ray heatmaps.
  const std::vector<uint64_t>& raysPerPixel() const { return raysPerPixel_; }
  const RenderStats& stats() const { return stats_; }
  const RenderSettings& settings() const { return settings_; }
  const TodoLog& todos() const { return todos_; }  // the unfinished stage code its tiles ran
  const PixelFilter& filter() const { return filter_; }

 private:
  struct Tile;
  void renderTile(Tile& tile, uint32_t firstSample, uint32_t sampleCount,
                  const std::atomic<bool>* cancel);
  void renderTileInBatches(Tile& tile, uint32_t firstSample, uint32_t sampleCount,
                           const std::atomic<bool>* cancel);
  void splatSample(Tile& tile, Vec2 filmPosition, const Color& radiance);
  void mergeBlocks();

  const RayTracer& tracer_;
  const Camera& camera_;
  const Integrator& integrator_;
  const WavefrontIntegrator* wavefront_;  // when the integrator renders batches
  const Stage1Functions& stage1_;
  RenderSettings settings_;
  PixelFilter filter_;
  Sampler sampler_;
  Film film_;
  std::vector<uint64_t> raysPerPixel_;
  std::vector<Tile> tiles_;
  bool blocksHoldSums_ = false;  // finished passes not yet merged into film_
  std::unique_ptr<tbb::task_arena> arena_;
  RenderStats stats_;
  TodoLog todos_;
};

}  // namespace pathway
