#include "sampling/sampler.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <iterator>

#include "core/error.h"
#include "sampling/hash.h"
#include "sampling/pcg32.h"  // toUnitFloat
#include "sampling/sobol.h"

namespace pathway {

namespace {

const char* const kSamplerNames[] = {"independent", "stratified", "sobol"};

// Salts keep seeds drawn for different purposes apart even when their other inputs coincide.
constexpr uint64_t kIndexShuffleSalt = 0x5348554646u;    // "SHUFF"
constexpr uint64_t kValueScrambleSalt = 0x5343524du;     // "SCRM"
constexpr uint64_t kStrataShuffleSalt = 0x535452415441;  // "STRATA"

// Sobol': the index shuffle is per block of four dimensions, the value scramble per dimension.
// Seeds derived from pixelKey, which is already a hash: one more mixing step per value is enough.
uint32_t sobolShuffleSeed(uint64_t pixelKey, uint32_t dimension) {
  return static_cast<uint32_t>(hashCombine(pixelKey ^ kIndexShuffleSalt, dimension / 4));
}

// The value-scramble seeds of dimensions firstDimension .. + count - 1 (count even): one hash
// per pair of dimensions gives both (its low and high halves).
void sobolValueSeeds(uint64_t pixelKey, uint32_t firstDimension, uint32_t count, uint32_t seeds[]) {
  for (uint32_t d = 0; d < count; d += 2) {
    const uint64_t bits = hashCombine(pixelKey ^ kValueScrambleSalt, (firstDimension + d) / 2);
    seeds[d] = static_cast<uint32_t>(bits);
    seeds[d + 1] = static_cast<uint32_t>(bits >> 32);
  }
}

// Dimensions firstDimension .. + 3 (one block of four) of sample `index`, as 32-bit fractions.
void sobolBlock(uint64_t pixelKey, uint32_t index, uint32_t firstDimension, uint32_t values[4]) {
  uint32_t seeds[4];
  sobolValueSeeds(pixelKey, firstDimension, 4, seeds);
  owenScrambledSobolBlock(reverseBits(index), sobolShuffleSeed(pixelKey, firstDimension), seeds,
                          values);
}

// Independent: 64 random bits per pair of dimensions, a hash of (pixel, index, pair); the even
// dimension takes the low half, the odd one the high half. Any dimension costs two mixing steps:
// no generator to seed and no stepping past the dimensions before it. The first step, the
// sample's key, is shared by all of the sample's pairs.
uint64_t independentSampleKey(uint64_t pixelKey, uint32_t index) {
  return hashCombine(pixelKey, index);
}

uint64_t independentPairBits(uint64_t sampleKey, uint32_t dimension) {
  return hashCombine(sampleKey, dimension / 2);
}

// Dimensions `dimension` (even) and `dimension + 1`.
Vec2 independentPair(uint64_t sampleKey, uint32_t dimension) {
  const uint64_t bits = independentPairBits(sampleKey, dimension);
  return Vec2(toUnitFloat(static_cast<uint32_t>(bits)),
              toUnitFloat(static_cast<uint32_t>(bits >> 32)));
}

uint32_t independentBits(uint64_t pixelKey, uint32_t index, uint32_t dimension) {
  const uint64_t bits = independentPairBits(independentSampleKey(pixelKey, index), dimension);
  return static_cast<uint32_t>(dimension % 2 == 0 ? bits : bits >> 32);
}

// Kensler 2013, "Correlated Multi-Jittered Sampling": element i of a pseudo-random permutation
// of 0..count-1 chosen by `pattern`. The loop body is a hash that is a bijection on the bits
// below the next power of two; "cycle walking" repeats it until the value lands below `count`.
uint32_t permute(uint32_t i, uint32_t count, uint32_t pattern) {
  uint32_t w = count - 1;  // mask: all bits below the next power of two
  w |= w >> 1;
  w |= w >> 2;
  w |= w >> 4;
  w |= w >> 8;
  w |= w >> 16;
  const uint32_t p = pattern;
  do {
    i ^= p;
    i *= 0xe170893d;
    i ^= p >> 16;
    i ^= (i & w) >> 4;
    i ^= p >> 8;
    i *= 0x0929eb3f;
    i ^= p >> 23;
    i ^= (i & w) >> 1;
    i *= 1 | p >> 27;
    i *= 0x6935fa69;
    i ^= (i & w) >> 11;
    i *= 0x74dcb303;
    i ^= (i & w) >> 2;
    i *= 0x9e501cc3;
    i ^= (i & w) >> 2;
    i *= 0xc860a3df;
    i &= w;
    i ^= i >> 5;
  } while (i >= count);
  // A final rotation by the pattern. (The paper's `(i + p) % l` can overflow and then map two
  // elements to one; reducing p first keeps it a permutation.)
  return (i + p % count) % count;
}

// A uniformly jittered point of stratum `cell` of `count` equal strata of [0, 1). It is built as
// a 24-bit fixed-point number q / 2^24, exact in a float, taking exactly the q for which
// floor(q * count / 2^24) == cell: so float rounding can never push a sample into the next
// stratum or up to 1.0, which computing (cell + jitter) / count in floats can.
float jitterInStratum(uint32_t cell, uint32_t count, uint32_t randomBits) {
  const uint64_t first = ((uint64_t(cell) << 24) + count - 1) / count;    // ceil(cell 2^24 / n)
  const uint64_t end = ((uint64_t(cell + 1) << 24) + count - 1) / count;  // first q of next cell
  const uint64_t q = first + (((end - first) * randomBits) >> 32);
  return static_cast<float>(q) * 0x1p-24f;
}

}  // namespace

SamplerType parseSamplerType(const std::string& name) {
  std::string choices;
  for (SamplerType type : {SamplerType::Independent, SamplerType::Stratified, SamplerType::Sobol}) {
    if (name == samplerTypeName(type)) return type;
    choices += (choices.empty() ? "" : ", ") + samplerTypeName(type);
  }
  throw PathwayError("unknown sampler \"" + name + "\" (valid choices: " + choices + ")");
}

std::string samplerTypeName(SamplerType type) {
  return kSamplerNames[static_cast<int>(type)];
}

std::vector<std::string> samplerTypeNames() {
  return std::vector<std::string>(std::begin(kSamplerNames), std::end(kSamplerNames));
}

Sampler::Sampler(SamplerType type, uint32_t samplesPerPixel, uint64_t seed)
    : type_(type), samplesPerPixel_(samplesPerPixel), seed_(seed) {
  // The most square grid with at least samplesPerPixel cells: strataX = floor(sqrt(n)).
  const uint32_t n = std::max(samplesPerPixel, 1u);
  uint32_t x = static_cast<uint32_t>(std::sqrt(static_cast<double>(n)));
  while (uint64_t(x) * x > n) --x;  // guard against sqrt rounding up
  while (uint64_t(x + 1) * (x + 1) <= n) ++x;
  strataX_ = x;
  strataY_ = (n + x - 1) / x;
}

uint64_t Sampler::pixelKey(uint32_t px, uint32_t py) const {
  return hashValues(px, py, seed_);
}

float Sampler::get(uint32_t px, uint32_t py, uint32_t index, uint32_t dimension) const {
  return get(pixelKey(px, py), index, dimension);
}

Vec2 Sampler::get2D(uint64_t pixelKey, uint32_t index, uint32_t dimension) const {
  // The same values as get(dimension) and get(dimension + 1), with the shared work done once:
  // for the independent sampler both halves of one hash.
  if (type_ == SamplerType::Independent)
    return independentPair(independentSampleKey(pixelKey, index), dimension);
  if (type_ == SamplerType::Sobol) {
    // Both dimensions lie in one block of four.
    uint32_t values[4];
    sobolBlock(pixelKey, index, dimension - dimension % 4, values);
    return Vec2(toUnitFloat(values[dimension % 4]), toUnitFloat(values[dimension % 4 + 1]));
  }
  return Vec2(get(pixelKey, index, dimension), get(pixelKey, index, dimension + 1));
}

void Sampler::getBlock(uint64_t pixelKey, uint32_t index, uint32_t firstDimension, uint32_t count,
                       float values[]) const {
  if (type_ == SamplerType::Sobol) {
    // One 4D Sobol' point per four dimensions; eight are two points, scrambled side by side in
    // vector lanes.
    if (count == kMaxBlockDimensions) {
      const uint32_t shuffleSeeds[2] = {sobolShuffleSeed(pixelKey, firstDimension),
                                        sobolShuffleSeed(pixelKey, firstDimension + 4)};
      uint32_t valueSeeds[kMaxBlockDimensions];
      sobolValueSeeds(pixelKey, firstDimension, count, valueSeeds);
      owenScrambledSobolFloats8(reverseBits(index), shuffleSeeds, valueSeeds, values);
      return;
    }
    assert(count == kMinBlockDimensions);
    uint32_t bits[kMinBlockDimensions];
    sobolBlock(pixelKey, index, firstDimension, bits);
    for (uint32_t d = 0; d < count; ++d) values[d] = toUnitFloat(bits[d]);
    return;
  }
  // Independent: the sample's key once for all pairs of the block.
  const uint64_t sampleKey =
      type_ == SamplerType::Independent ? independentSampleKey(pixelKey, index) : 0;
  for (uint32_t d = 0; d < count; d += 2) {
    const Vec2 pair = type_ == SamplerType::Independent
                          ? independentPair(sampleKey, firstDimension + d)
                          : get2D(pixelKey, index, firstDimension + d);
    values[d] = pair.x;
    values[d + 1] = pair.y;
  }
}

float Sampler::get(uint64_t pixelKey, uint32_t index, uint32_t dimension) const {
  switch (type_) {
    case SamplerType::Independent:
      return toUnitFloat(independentBits(pixelKey, index, dimension));

    case SamplerType::Stratified: {
      // Dimensions (2k, 2k+1) share a jittered strataX x strataY grid. Sample `index` gets cell
      // permute(index): a different shuffle per pixel and per pair, so pairs are not correlated.
      const uint64_t cells = uint64_t(strataX_) * strataY_;
      const uint32_t randomBits = independentBits(pixelKey, index, dimension);
      if (index >= cells) return toUnitFloat(randomBits);  // past the plan: plain random
      const auto pattern =
          static_cast<uint32_t>(hashCombine(pixelKey ^ kStrataShuffleSalt, dimension / 2));
      const uint32_t cell = permute(index, static_cast<uint32_t>(cells), pattern);
      if (dimension % 2 == 0) return jitterInStratum(cell % strataX_, strataX_, randomBits);
      return jitterInStratum(cell / strataX_, strataY_, randomBits);
    }

    case SamplerType::Sobol: {
      // Burley's "shuffled, scrambled" Sobol' with padding: dimensions are grouped in blocks of
      // four. A block's dimensions come from ONE 4D Sobol' point (so, e.g., pixel position 0-1
      // and AO direction 2-3 are stratified jointly), and each block shuffles the sample order
      // on its own, which decorrelates blocks. Each pixel has its own scrambles.
      // Owen-scrambling the index maps every aligned block of 2^m indices onto another one, so
      // the first 2^m samples of a pixel are still a whole block of the sequence: a net.
      // (owenScrambledSobolBlock computes exactly that, with the bit reversals folded into
      // tables.)
      uint32_t values[4];
      sobolBlock(pixelKey, index, dimension - dimension % 4, values);
      return toUnitFloat(values[dimension % 4]);
    }
  }
  return 0.0f;  // unreachable: every SamplerType is handled above
}

}  // namespace pathway
