// The Sobol' sequence (Joe & Kuo direction numbers) and hash-based Owen scrambling (Burley 2020,
// "Practical Hash-based Owen Scrambling", JCGT 9(4)).
//
// Values are 32-bit fixed-point fractions: x / 2^32 is the coordinate in [0, 1).
#pragma once

#include <cstdint>

namespace pathway {

// Dimensions with generator matrices: dimension 0 is van der Corput, 1..63 come from the first
// lines of new-joe-kuo-6.21201 (see sobol_joe_kuo.inc).
constexpr uint32_t kSobolDimensions = 64;

// Coordinate `dimension` (< kSobolDimensions) of point `index` of the unscrambled sequence, in
// natural order (not Gray-code order), so point i is a pure function of i. Every aligned block of
// 2^m consecutive points is a net; dimension 0 is the bit reversal of `index`.
uint32_t sobolSample(uint32_t index, uint32_t dimension);

// Nested uniform (Owen) scrambling in base 2 of a 32-bit fraction: each bit is flipped by a
// pseudo-random function of the bits above it, as Owen's random tree of permutations does.
// Keeps every (t,m,s)-net a (t,m,s)-net with the same t. Also a bijection on 32-bit integers,
// which is what makes it usable for shuffling sample indices.
uint32_t nestedUniformScramble(uint32_t x, uint32_t seed);

inline uint32_t reverseBits(uint32_t x) {
  x = __builtin_bswap32(x);  // the bytes in one instruction, then the bits within each byte
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
  return x;
}

// The sampler's fast path: the same values as
//   nestedUniformScramble(sobolSample(nestedUniformScramble(index, shuffleSeed), d), valueSeeds[d])
// for the four dimensions d = 0..3 of one block, given reverseBits(index). Scrambling works on
// reversed bits, so the tables behind it take the reversed shuffled index and give the reversed
// coordinate: of the 3 + 2·4 bit reversals the formula spells out, one per value is left (and
// one per sample, by the caller), and the shuffle is done once for the four.
void owenScrambledSobolBlock(uint32_t reversedIndex, uint32_t shuffleSeed,
                             const uint32_t valueSeeds[4], uint32_t values[4]);

// The same for two blocks at once, dimensions 0..3 of block 0 (shuffleSeeds[0], valueSeeds[0..3])
// then those of block 1 (shuffleSeeds[1], valueSeeds[4..7]), turned into floats as toUnitFloat
// does. The eight scrambles and bit reversals run side by side in vector registers (AVX2 where the
// processor has it, chosen on the first call): the scalar path spent its time there.
void owenScrambledSobolFloats8(uint32_t reversedIndex, const uint32_t shuffleSeeds[2],
                               const uint32_t valueSeeds[8], float values[8]);
// Its two versions, for the tests: any processor, and an x86 one with AVX2 (call it only where
// processorHasAvx2(); elsewhere it is the portable version).
void owenScrambledSobolFloats8Portable(uint32_t reversedIndex, const uint32_t shuffleSeeds[2],
                                       const uint32_t valueSeeds[8], float values[8]);
void owenScrambledSobolFloats8Avx2(uint32_t reversedIndex, const uint32_t shuffleSeeds[2],
                                   const uint32_t valueSeeds[8], float values[8]);
bool processorHasAvx2();

}  // namespace pathway
