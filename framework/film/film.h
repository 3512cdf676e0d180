// The film: per-pixel sums of filter-weighted samples. A pixel's value is Σ f·L / Σ f (the
// lecture's numerical normalisation); the extra moments give the variance of that ratio for the
// grader.
//
// Rendering writes into FilmBlocks (one per tile, covering the tile plus the filter's reach) and
// the blocks are merged into the Film in a fixed order, so the image never depends on thread
// timing.
#pragma once

#include <vector>

#include "core/math.h"

namespace pathway {

// Per-pixel sums, in double: with a negative-lobed filter Σ w·L and Σ w can nearly cancel, and
// the constant-scene guarantee (Σ w·C / Σ w = C) needs the products w·L summed without rounding.
struct PixelSums {
  using Real = double;
  using Vec = glm::dvec3;
  Vec weightedRadiance{0};        // Σ w·L
  Real weight = 0;                // Σ w
  Real absWeight = 0;             // Σ |w|, to tell "Σw ≈ 0" from "no samples"
  Vec squaredWeightRadiance{0};   // Σ w²·L
  Vec squaredWeightRadiance2{0};  // Σ w²·L²
  Real squaredWeight = 0;         // Σ w²
  uint32_t sampleCount = 0;       // splats with w != 0

  void add(Real w, const Vec& radiance) {
    if (w == 0) return;
    const Real w2 = w * w;
    weightedRadiance += w * radiance;
    weight += w;
    absWeight += w < 0 ? -w : w;
    squaredWeightRadiance += w2 * radiance;
    squaredWeightRadiance2 += w2 * radiance * radiance;
    squaredWeight += w2;
    ++sampleCount;
  }
  PixelSums& operator+=(const PixelSums& o) {
    weightedRadiance += o.weightedRadiance;
    weight += o.weight;
    absWeight += o.absWeight;
    squaredWeightRadiance += o.squaredWeightRadiance;
    squaredWeightRadiance2 += o.squaredWeightRadiance2;
    squaredWeight += o.squaredWeight;
    sampleCount += o.sampleCount;
    return *this;
  }
  PixelSums& operator-=(const PixelSums& o) {
    weightedRadiance -= o.weightedRadiance;
    weight -= o.weight;
    absWeight -= o.absWeight;
    squaredWeightRadiance -= o.squaredWeightRadiance;
    squaredWeightRadiance2 -= o.squaredWeightRadiance2;
    squaredWeight -= o.squaredWeight;
    sampleCount -= o.sampleCount;
    return *this;
  }
};

// A rectangle of pixel sums in image coordinates. Splats outside the image are ignored.
class FilmBlock {
 public:
  FilmBlock() = default;
  // The block covers pixels [x0, x0 + width) x [y0, y0 + height) clipped to the image.
  FilmBlock(int imageWidth, int imageHeight, int x0, int y0, int width, int height);

  // Adds one filter-weighted sample to pixel (x, y): Σ w·L and Σ w (and the variance moments).
  // Inline: every splat of every render calls it for each pixel in reach.
  void addSample(int x, int y, float weight, const Color& radiance) {
    if (x < x0_ || y < y0_ || x >= x0_ + width_ || y >= y0_ + height_) return;
    sums_[static_cast<size_t>(y - y0_) * width_ + (x - x0_)].add(weight, glm::dvec3(radiance));
  }
  void clear();

  int x0() const { return x0_; }
  int y0() const { return y0_; }
  int width() const { return width_; }
  int height() const { return height_; }
  const PixelSums& at(int x, int y) const { return sums_[(y - y0_) * width_ + (x - x0_)]; }
  PixelSums& at(int x, int y) { return sums_[(y - y0_) * width_ + (x - x0_)]; }

 private:
  int x0_ = 0, y0_ = 0, width_ = 0, height_ = 0;
  std::vector<PixelSums> sums_;
};

// A developed image: one RGB float triple per pixel, rows top to bottom.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;

  Image() = default;
  Image(int w, int h) : width(w), height(h), pixels(static_cast<size_t>(w) * h, Color(0.0f)) {}
  Color& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
  const Color& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

class Film {
 public:
  Film(int width, int height);

  // Adds the block's sums to the film and leaves the block empty for the next pass: one pass over
  // its memory instead of a merge and a separate clear.
  void merge(FilmBlock& block);
  // Adds another film's sums pixel by pixel: two renders over disjoint sample ranges become the
  // one render over both (up to the order of the floating-point additions).
  Film& operator+=(const Film& other);
  // Takes an earlier state of the same render away: what the passes since then added (the
  // grader's jackknife, grade/jackknife_render.h).
  Film& operator-=(const Film& earlier);
  void clear();

  // Σ w·L / Σ w per pixel. Where |Σ w| is tiny next to Σ |w| (possible with a negative-lobed
  // filter at low sample counts) the ratio is meaningless; such pixels come out 0 and are counted.
  Image develop(size_t* unresolvedPixels = nullptr) const;
  // Estimated variance of each developed pixel value (delta method for the ratio Σ w·L / Σ w).
  Image variance() const;
  Image weights() const;  // Σ w in every channel
  // All three in one pass over the sums (what a render hands on; the viewer, whenever it publishes
  // an image).
  void developAll(Image& color, Image& variance, Image& weights,
                  size_t* unresolvedPixels = nullptr) const;

  int width() const { return width_; }
  int height() const { return height_; }
  const PixelSums& at(int x, int y) const { return sums_[static_cast<size_t>(y) * width_ + x]; }
  PixelSums& at(int x, int y) { return sums_[static_cast<size_t>(y) * width_ + x]; }

 private:
  int width_, height_;
  std::vector<PixelSums> sums_;
};

}  // namespace pathway
