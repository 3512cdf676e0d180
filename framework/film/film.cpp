#include "film/film.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"

namespace pathway {
namespace {

// |Σw| below this fraction of Σ|w| means the positive and negative filter lobes cancelled.
constexpr double kUnresolvedWeightFraction = 1e-6;

bool isResolved(const PixelSums& p) {
  return p.absWeight > 0.0 && std::fabs(p.weight) > kUnresolvedWeightFraction * p.absWeight;
}

Color developedValue(const PixelSums& p) {
  return Color(p.weightedRadiance / p.weight);
}

// Σ w²(L - I)² / (Σ w)², expanded so it can be accumulated sample by sample.
Color developedVariance(const PixelSums& p) {
  const glm::dvec3 mean = p.weightedRadiance / p.weight;
  const glm::dvec3 spread = p.squaredWeightRadiance2 - 2.0 * mean * p.squaredWeightRadiance +
                            mean * mean * p.squaredWeight;
  return Color(glm::max(spread, glm::dvec3(0.0)) / (p.weight * p.weight));
}

}  // namespace

FilmBlock::FilmBlock(int imageWidth, int imageHeight, int x0, int y0, int width, int height) {
  x0_ = std::max(0, x0);
  y0_ = std::max(0, y0);
  width_ = std::max(0, std::min(imageWidth, x0 + width) - x0_);
  height_ = std::max(0, std::min(imageHeight, y0 + height) - y0_);
  sums_.resize(static_cast<size_t>(width_) * height_);
}

void FilmBlock::clear() {
  std::fill(sums_.begin(), sums_.end(), PixelSums{});
}

Film::Film(int width, int height)
    : width_(width), height_(height), sums_(static_cast<size_t>(width) * height) {}

void Film::merge(FilmBlock& block) {
  for (int y = block.y0(); y < block.y0() + block.height(); ++y)
    for (int x = block.x0(); x < block.x0() + block.width(); ++x) {
      PixelSums& sums = block.at(x, y);
      sums_[static_cast<size_t>(y) * width_ + x] += sums;
      sums = PixelSums{};
    }
}

Film& Film::operator+=(const Film& other) {
  if (other.width_ != width_ || other.height_ != height_)
    throw PathwayError("internal: adding films of different sizes");
  for (size_t i = 0; i < sums_.size(); ++i) sums_[i] += other.sums_[i];
  return *this;
}

Film& Film::operator-=(const Film& earlier) {
  if (earlier.width_ != width_ || earlier.height_ != height_)
    throw PathwayError("internal: subtracting films of different sizes");
  for (size_t i = 0; i < sums_.size(); ++i) sums_[i] -= earlier.sums_[i];
  return *this;
}

void Film::clear() {
  std::fill(sums_.begin(), sums_.end(), PixelSums{});
}

Image Film::develop(size_t* unresolvedPixels) const {
  Image image(width_, height_);
  size_t unresolved = 0;
  for (size_t i = 0; i < sums_.size(); ++i) {
    const PixelSums& p = sums_[i];
    if (isResolved(p)) {
      image.pixels[i] = developedValue(p);
    } else if (p.absWeight > 0.0) {
      ++unresolved;
    }
  }
  if (unresolvedPixels) *unresolvedPixels = unresolved;
  return image;
}

Image Film::variance() const {
  Image image(width_, height_);
  for (size_t i = 0; i < sums_.size(); ++i)
    if (isResolved(sums_[i])) image.pixels[i] = developedVariance(sums_[i]);
  return image;
}

Image Film::weights() const {
  Image image(width_, height_);
  for (size_t i = 0; i < sums_.size(); ++i)
    image.pixels[i] = Color(static_cast<float>(sums_[i].weight));
  return image;
}

void Film::developAll(Image& color, Image& variance, Image& weights,
                      size_t* unresolvedPixels) const {
  color = variance = weights = Image(width_, height_);
  size_t unresolved = 0;
  for (size_t i = 0; i < sums_.size(); ++i) {
    const PixelSums& p = sums_[i];
    weights.pixels[i] = Color(static_cast<float>(p.weight));
    if (isResolved(p)) {
      color.pixels[i] = developedValue(p);
      variance.pixels[i] = developedVariance(p);
    } else if (p.absWeight > 0.0) {
      ++unresolved;
    }
  }
  if (unresolvedPixels) *unresolvedPixels = unresolved;
}

}  // namespace pathway
