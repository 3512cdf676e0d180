// Samplers: a sample value is a pure function of (pixel, sample index, dimension, seed), so an
// image does not depend on thread count, tile order or how many passes it took.
//
// Dimensions are consumed in a fixed order by every integrator: 0-1 place the sample in the pixel,
// then each stage takes the next ones (4D AO takes 2-3 for its AO direction).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/math.h"

namespace pathway {

enum class SamplerType {
  Independent,  // hashed bits: one 64-bit hash of (pixel, index, dimension pair, seed) per pair
  Stratified,   // jittered strata per pair of dimensions, strata shuffled per pixel and pair
  Sobol,        // Owen-scrambled Sobol' (Joe-Kuo direction numbers), hash-based nested scrambling
};

// "independent", "stratified", "sobol"; throws PathwayError naming the valid choices otherwise.
SamplerType parseSamplerType(const std::string& name);
std::string samplerTypeName(SamplerType type);
std::vector<std::string> samplerTypeNames();

class Sampler {
 public:
  // `samplesPerPixel` is the planned total; the stratified sampler sizes its strata from it.
  // Indices past it stay valid and unbiased (they are simply not stratified against the rest).
  Sampler(SamplerType type, uint32_t samplesPerPixel, uint64_t seed);

  // The sample value in [0, 1) of `dimension` for sample `index` of `pixel`.
  float get(uint32_t pixelX, uint32_t pixelY, uint32_t index, uint32_t dimension) const;
  // The same, with the pixel's hash (pixelKey) computed once by the caller: the fast path.
  float get(uint64_t pixelKey, uint32_t index, uint32_t dimension) const;
  // Dimensions `dimension` (even) and `dimension + 1` together: the same values, faster.
  Vec2 get2D(uint64_t pixelKey, uint32_t index, uint32_t dimension) const;
  // The four dimensions firstDimension .. firstDimension + 3 (firstDimension a multiple of 4):
  // the same values as get(), with the work they share done once.
  void getBlock(uint64_t pixelKey, uint32_t index, uint32_t firstDimension, float values[4]) const;
  // A hash of (pixel, seed): every sampler's randomisation starts from it.
  uint64_t pixelKey(uint32_t pixelX, uint32_t pixelY) const;

  uint32_t samplesPerPixel() const { return samplesPerPixel_; }

 private:
  SamplerType type_;
  uint32_t samplesPerPixel_;
  uint64_t seed_;
  uint32_t strataX_, strataY_;  // stratified: strata per dimension pair
};

// Walks the dimensions of one camera sample in order. Integrators take their numbers from here.
// It draws them four at a time (Sampler::getBlock): the values of a block share work (Sobol':
// one index shuffle; independent: one hash per pair) and are computed side by side.
class SampleStream {
 public:
  SampleStream(const Sampler& sampler, uint32_t pixelX, uint32_t pixelY, uint32_t index)
      : SampleStream(sampler, sampler.pixelKey(pixelX, pixelY), index) {}
  // With the pixel's key (Sampler::pixelKey) computed once for all of its samples.
  SampleStream(const Sampler& sampler, uint64_t pixelKey, uint32_t index)
      : sampler_(&sampler), pixelKey_(pixelKey), index_(index) {}

  float next1D() {
    const float u = current();
    ++dimension_;
    return u;
  }
  Vec2 next2D() {
    // Pairs start on even dimensions, so a pair is always one stratified/Sobol' 2D projection
    // (and never straddles two blocks of four).
    if (dimension_ % 2 == 1) ++dimension_;
    const float u = current();
    const Vec2 uv(u, block_[dimension_ % 4 + 1]);
    dimension_ += 2;
    return uv;
  }
  uint32_t dimension() const { return dimension_; }

 private:
  float current() {
    const uint32_t first = dimension_ - dimension_ % 4;
    if (first != blockStart_) {
      sampler_->getBlock(pixelKey_, index_, first, block_);
      blockStart_ = first;
    }
    return block_[dimension_ % 4];
  }

  const Sampler* sampler_;
  uint64_t pixelKey_;
  uint32_t index_;
  uint32_t dimension_ = 0;
  uint32_t blockStart_ = 1;  // the first dimension block_ holds (1: none yet)
  float block_[4];
};

}  // namespace pathway
