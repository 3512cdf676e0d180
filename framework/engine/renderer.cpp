#include "engine/renderer.h"

#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/error.h"
#include "engine/pixel_in_progress.h"
#include "render/wavefront.h"

namespace pathway {

struct Renderer::Tile {
  int x0, y0, x1, y1;  // the pixels whose samples this tile draws
  int mergeClass;      // tiles of one class never overlap, so a class merges in parallel
  FilmBlock block;     // the tile plus the filter's reach: finished passes' sums until merged
  RayCounters counters;
  std::vector<uint64_t> rays;  // per pixel of the tile, this pass
};

namespace {

const RenderSettings& checked(const RenderSettings& settings) {
  settings.check();
  return settings;
}

}  // namespace

Renderer::Renderer(const RayTracer& tracer, const Camera& camera, const Integrator& integrator,
                   const Stage1Functions& stage1, const RenderSettings& settings)
    : tracer_(tracer),
      camera_(camera),
      integrator_(integrator),
      wavefront_(integrator.asWavefront()),
      stage1_(stage1),
      settings_(checked(settings)),
      filter_(settings.filter, settings.filterRadiusPixels(), stage1.profiles),
      sampler_(settings.sampler, settings.samplesPerPixel, settings.seed),
      film_(settings.width, settings.height),
      raysPerPixel_(static_cast<size_t>(settings_.width) * settings_.height, 0) {
  // A sample drawn in pixel i reaches pixels whose centres lie within the filter radius.
  // Pixel j's centre j + 0.5 is within r of a sample in [i, i+1) only if |j - i| <= ceil(r + 0.5).
  const int margin = static_cast<int>(std::ceil(filter_.radius() + 0.5f));
  const int size = settings_.tileSize;
  // Same-class tiles are two tiles apart; they cannot overlap if the margin is under a tile.
  if (2 * margin >= size)
    throw PathwayError("filter radius " + std::to_string(filter_.radius()) +
                       " is too wide for tiles of " + std::to_string(size) + " pixels");
  for (int ty = 0; ty * size < settings_.height; ++ty) {
    for (int tx = 0; tx * size < settings_.width; ++tx) {
      Tile tile;
      tile.x0 = tx * size;
      tile.y0 = ty * size;
      tile.x1 = std::min(settings_.width, tile.x0 + size);
      tile.y1 = std::min(settings_.height, tile.y0 + size);
      tile.mergeClass = (tx % 2) + 2 * (ty % 2);
      tile.rays.resize(static_cast<size_t>(tile.x1 - tile.x0) * (tile.y1 - tile.y0));
      tile.block = FilmBlock(settings_.width, settings_.height, tile.x0 - margin, tile.y0 - margin,
                             size + 2 * margin, size + 2 * margin);
      tiles_.push_back(std::move(tile));
    }
  }
  // More threads than cores would only be refused by TBB (with a warning), so cap them.
  const int cores = tbb::info::default_concurrency();
  const int threads = settings_.threads > 0 ? std::min(settings_.threads, cores) : cores;
  arena_ = std::make_unique<tbb::task_arena>(threads);
}

Renderer::~Renderer() = default;

void Renderer::renderTile(Tile& tile, uint32_t firstSample, uint32_t sampleCount,
                          const std::atomic<bool>* cancel) {
  if (wavefront_) return renderTileInBatches(tile, firstSample, sampleCount, cancel);
  tile.counters = RayCounters{};         // this pass's (the block adds to what earlier passes left)
  const CurrentTodoLog logged(&todos_);  // TODOs this thread runs now are this render's
  const RenderContext context(tracer_, tile.counters);
  uint64_t* pixelRays = tile.rays.data();
  // How many numbers the previous sample drew predicts the next one's (SampleStream).
  uint32_t expectedDimensions = Sampler::kMaxBlockDimensions;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x, ++pixelRays) {
      // Checked per pixel, so even a pass of many samples per pixel stops promptly.
      if (cancel && cancel->load(std::memory_order_relaxed)) return clearPixelInProgress();
      recordPixelInProgress(x, y);
      const uint64_t raysBefore = tile.counters.totalRays();
      const uint64_t pixelKey = sampler_.pixelKey(x, y);
      for (uint32_t index = firstSample; index < firstSample + sampleCount; ++index) {
        SampleStream samples(sampler_, pixelKey, index, expectedDimensions);
        const Vec2 filmPosition = Vec2(x, y) + samples.next2D();
        const Color radiance = integrator_.Li(camera_.generateRay(filmPosition), samples, context);
        expectedDimensions = samples.dimension();
        splatSample(tile, filmPosition, radiance);
      }
      *pixelRays = tile.counters.totalRays() - raysBefore;
    }
  }
  clearPixelInProgress();
}

void Renderer::splatSample(Tile& tile, Vec2 filmPosition, const Color& radiance) {
  if (!isFinite(radiance)) {  // counted and dropped, never written
    ++tile.counters.invalidSamples;
    return;
  }
  stage1_.splat(tile.block, filmPosition, radiance, filter_);
  ++tile.counters.samples;
}

// The same samples in the same order as renderTile, gathered into batches for a wavefront
// integrator; each batch's results are splatted in that order, so the tile's sums come out as
// if its samples had been rendered one by one.
void Renderer::renderTileInBatches(Tile& tile, uint32_t firstSample, uint32_t sampleCount,
                                   const std::atomic<bool>* cancel) {
  tile.counters = RayCounters{};
  const CurrentTodoLog logged(&todos_);
  const RenderContext context(tracer_, tile.counters);
  std::fill(tile.rays.begin(), tile.rays.end(), 0);
  const size_t batchSize = wavefront_->batchSize();
  thread_local CameraSampleBatch batch;  // kept between tiles: no allocation per tile
  thread_local std::vector<Vec2> filmPositions;
  thread_local std::vector<uint32_t> pixelOfSample;  // index into tile.rays
  batch.clear();
  filmPositions.clear();
  pixelOfSample.clear();
  uint32_t expectedDimensions = Sampler::kMaxBlockDimensions;  // as in renderTile
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  // Renders the gathered samples and splats them; false when the render was cancelled first.
  auto flush = [&] {
    if (cancelled()) return false;
    wavefront_->LiBatch(batch, context);
    expectedDimensions = batch.samples.back().dimension();
    for (size_t i = 0; i < batch.size(); ++i) {
      splatSample(tile, filmPositions[i], batch.radiance[i]);
      tile.rays[pixelOfSample[i]] += batch.rays[i];
    }
    batch.clear();
    filmPositions.clear();
    pixelOfSample.clear();
    return true;
  };
  uint32_t pixel = 0;
  for (int y = tile.y0; y < tile.y1; ++y) {
    for (int x = tile.x0; x < tile.x1; ++x, ++pixel) {
      if (cancelled()) return clearPixelInProgress();
      // The pixel being gathered: a crash in LiBatch is in a batch that ends here.
      recordPixelInProgress(x, y);
      const uint64_t pixelKey = sampler_.pixelKey(x, y);
      for (uint32_t index = firstSample; index < firstSample + sampleCount; ++index) {
        SampleStream samples(sampler_, pixelKey, index, expectedDimensions);
        const Vec2 filmPosition = Vec2(x, y) + samples.next2D();
        batch.add(camera_.generateRay(filmPosition), samples);
        filmPositions.push_back(filmPosition);
        pixelOfSample.push_back(pixel);
        if (batch.size() == batchSize && !flush()) return clearPixelInProgress();
      }
    }
  }
  if (batch.size() > 0) flush();  // a cancelled pass is dropped whole, so its result may go
  clearPixelInProgress();
}

bool Renderer::renderPass(const std::atomic<bool>* cancel) {
  if (finished()) return true;
  const auto start = std::chrono::steady_clock::now();
  const uint32_t first = settings_.firstSample() + stats_.samplesPerPixel;
  const uint32_t count = std::min(settings_.samplesPerPass, settings_.endSample() - first);
  auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
  if (cancel) mergeBlocks();

  arena_->execute([&] {
    tbb::parallel_for(size_t(0), tiles_.size(), [&](size_t i) {
      if (!cancelled()) renderTile(tiles_[i], first, count, cancel);
    });
  });
  if (cancelled()) {
    // The finished tiles' sums belong to a pass that does not count: drop them.
    for (Tile& tile : tiles_) tile.block.clear();
    return false;
  }

  blocksHoldSums_ = true;
  for (const Tile& tile : tiles_) {
    stats_.counters += tile.counters;
    const uint64_t* pixelRays = tile.rays.data();
    for (int y = tile.y0; y < tile.y1; ++y)
      for (int x = tile.x0; x < tile.x1; ++x)
        raysPerPixel_[static_cast<size_t>(y) * settings_.width + x] += *pixelRays++;
  }
  stats_.samplesPerPixel += count;
  stats_.seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return true;
}

void Renderer::mergeBlocks() {
  if (!blocksHoldSums_) return;
  // Class by class (each class in parallel, its tiles disjoint); every pixel then receives its
  // contributions in the same order whatever the thread count.
  arena_->execute([&] {
    for (int mergeClass = 0; mergeClass < 4; ++mergeClass) {
      tbb::parallel_for(size_t(0), tiles_.size(), [&](size_t i) {
        if (tiles_[i].mergeClass == mergeClass) film_.merge(tiles_[i].block);
      });
    }
  });
  blocksHoldSums_ = false;
}

const Film& Renderer::film() {
  mergeBlocks();
  return film_;
}

bool Renderer::renderAll(const std::function<void(const RenderStats&)>& onPass,
                         const std::atomic<bool>* cancel) {
  while (!finished()) {
    if (!renderPass(cancel)) return false;
    if (onPass) onPass(stats_);
  }
  return true;
}

}  // namespace pathway
