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
  // Dimensions firstDimension .. firstDimension + count - 1 (firstDimension a multiple of 4,
  // count 4 or 8): the same values as get(), with the work they share done once and side by side.
  static constexpr uint32_t kMinBlockDimensions = 4;  // one Sobol' point
  static constexpr uint32_t kMaxBlockDimensions = 8;
  void getBlock(uint64_t pixelKey, uint32_t index, uint32_t firstDimension, uint32_t count,
                float values[]) const;
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
// It draws them in blocks (Sampler::getBlock): the values of a block share work (Sobol': one
// index shuffle per four; independent: one hash per pair) and are computed side by side, so their
// latencies overlap. A path tracer takes about eight dimensions per bounce, so blocks hold eight:
// a bounce waits for one block, not two, and the first block (drawn before the camera ray is
// traced) already holds the first bounce's numbers. An integrator that needs only dimensions
// 0-3 (4D AO) would waste half of such a block, so the first block's size follows the caller's
// guess of how many numbers the sample will draw (the renderer's: as many as the previous
// sample drew). The values never depend on the block sizes.
class SampleStream {
 public:
  // Sample `index` of the pixel whose key (Sampler::pixelKey) is `pixelKey`: the key is computed
  // once for all of a pixel's samples. `expectedDimensions`: how many numbers the sample will
  // probably draw; up to 4 makes the first block 4 dimensions, more makes it 8 (see above).
  SampleStream(const Sampler& sampler, uint64_t pixelKey, uint32_t index,
               uint32_t expectedDimensions = Sampler::kMaxBlockDimensions)
      : sampler_(&sampler),
        pixelKey_(pixelKey),
        index_(index),
        firstBlockDimensions_(expectedDimensions <= Sampler::kMinBlockDimensions
                                  ? Sampler::kMinBlockDimensions
                                  : Sampler::kMaxBlockDimensions) {}

  float next1D() {
    const float u = current();
    ++dimension_;
    return u;
  }
  Vec2 next2D() {
    // Pairs start on even dimensions, so a pair is always one stratified/Sobol' 2D projection
    // (and never straddles two blocks).
    if (dimension_ % 2 == 1) ++dimension_;
    const float u = current();
    const Vec2 uv(u, block_[dimension_ - blockStart_ + 1]);
    dimension_ += 2;
    return uv;
  }
  uint32_t dimension() const { return dimension_; }

 private:
  float current() {
    if (dimension_ - blockStart_ >= blockSize_) {
      if (dimension_ < firstBlockDimensions_) {
        blockStart_ = 0, blockSize_ = firstBlockDimensions_;
      } else {  // blocks of eight after the first
        blockSize_ = Sampler::kMaxBlockDimensions;
        blockStart_ = dimension_ - (dimension_ - firstBlockDimensions_) % blockSize_;
      }
      sampler_->getBlock(pixelKey_, index_, blockStart_, blockSize_, block_);
    }
    return block_[dimension_ - blockStart_];
  }

  const Sampler* sampler_;
  uint64_t pixelKey_;
  uint32_t index_;
  uint32_t firstBlockDimensions_;
  uint32_t dimension_ = 0;
  uint32_t blockStart_ = 0;  // block_ holds dimensions blockStart_ .. + blockSize_ - 1
  uint32_t blockSize_ = 0;   // (none yet)
  float block_[Sampler::kMaxBlockDimensions];
};

}  // namespace pathway
