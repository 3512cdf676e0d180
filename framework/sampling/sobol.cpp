#include "sampling/sobol.h"

#include <array>
#include <cassert>
#include <cstring>
#include <iterator>

namespace pathway {
namespace {

// One line of Joe & Kuo's table: d s a m_1 .. m_s.
constexpr uint32_t kMaxDegree = 9;  // the largest s among the lines we keep
struct JoeKuoRow {
  uint32_t d, s, a;
  uint32_t m[kMaxDegree];
};

constexpr JoeKuoRow kJoeKuo[] = {
#include "sampling/sobol_joe_kuo.inc"
};
static_assert(std::size(kJoeKuo) + 1 == kSobolDimensions, "one row per dimension after the first");

// Catches a lost or mistyped line at compile time: rows are consecutive and every m_k is odd and
// below 2^k, as the construction requires.
constexpr bool tableIsWellFormed() {
  for (uint32_t row = 0; row < std::size(kJoeKuo); ++row) {
    const JoeKuoRow& r = kJoeKuo[row];
    if (r.d != row + 2 || r.s == 0 || r.s > kMaxDegree || r.a >= (1u << (r.s - 1))) return false;
    for (uint32_t k = 0; k < r.s; ++k) {
      if (r.m[k] % 2 == 0 || r.m[k] >= (2u << k)) return false;
    }
  }
  return true;
}
static_assert(tableIsWellFormed(), "sobol_joe_kuo.inc is malformed");

// A generator matrix stored by columns: column k is what bit k of the index XORs into the result
// (the direction number v_{k+1} of Bratley & Fox, as a 32-bit fraction).
using Matrix = std::array<uint32_t, 32>;

constexpr Matrix generatorMatrix(uint32_t dimension) {
  Matrix v{};
  if (dimension == 0) {
    // van der Corput: index bit k becomes fraction bit k, i.e. the bits are reversed.
    for (uint32_t k = 0; k < 32; ++k) v[k] = 1u << (31 - k);
    return v;
  }
  const JoeKuoRow& row = kJoeKuo[dimension - 1];
  const uint32_t s = row.s;
  for (uint32_t k = 0; k < 32; ++k) {
    if (k < s) {
      v[k] = row.m[k] << (31 - k);  // m_k / 2^k as a 32-bit fraction
      continue;
    }
    // The recurrence given by the primitive polynomial x^s + a_1 x^(s-1) + ... + a_(s-1) x + 1:
    // v_k = a_1 v_(k-1) ^ ... ^ a_(s-1) v_(k-s+1) ^ v_(k-s) ^ (v_(k-s) >> s).
    v[k] = v[k - s] ^ (v[k - s] >> s);
    for (uint32_t j = 1; j < s; ++j) {
      if ((row.a >> (s - 1 - j)) & 1) v[k] ^= v[k - j];
    }
  }
  return v;
}

constexpr std::array<Matrix, kSobolDimensions> buildMatrices() {
  std::array<Matrix, kSobolDimensions> matrices{};
  for (uint32_t d = 0; d < kSobolDimensions; ++d) matrices[d] = generatorMatrix(d);
  return matrices;
}

// Built by the compiler: no start-up cost and no static-initialisation-order questions.
constexpr std::array<Matrix, kSobolDimensions> kMatrices = buildMatrices();

constexpr uint32_t reverseBitsConstexpr(uint32_t x) {
  uint32_t r = 0;
  for (uint32_t bit = 0; bit < 32; ++bit)
    if (x & (1u << bit)) r |= 1u << (31 - bit);
  return r;
}

// The first four dimensions (all the sampler draws from: it pads in blocks of four) also as
// byte tables for the Owen-scrambled paths (owenScrambledSobolBlock, owenScrambledSobolFloats8):
// the product with one byte of the index is one lookup, so a point costs four lookups instead of
// a loop over 32 index bits.
// Both ends are bit-reversed: the input byte is a byte of the reversed index (its bit j is index
// bit 31 - j), the output is the reversed coordinate. 16 KiB, built by the compiler as well.
using ByteTables = std::array<std::array<std::array<uint32_t, 256>, 4>, 4>;  // [dim][byte][value]
constexpr ByteTables buildReversedByteTables() {
  ByteTables tables{};
  for (uint32_t d = 0; d < 4; ++d)
    for (uint32_t byte = 0; byte < 4; ++byte)
      for (uint32_t value = 0; value < 256; ++value) {
        uint32_t x = 0;
        for (uint32_t bit = 0; bit < 8; ++bit)
          if (value & (1u << bit)) x ^= kMatrices[d][31 - (8 * byte + bit)];
        tables[d][byte][value] = reverseBitsConstexpr(x);
      }
  return tables;
}
constexpr ByteTables kReversedByteTables = buildReversedByteTables();

// Laine & Karras (2011), with Burley's constants. The constants are even, so `x * c` only carries
// bits upwards: bit j of the result depends on bits 0..j of the input alone. That makes it a
// bijection, and, applied to reversed bits, a scramble in which each bit depends only on the
// bits above it.
constexpr uint32_t kLaineKarrasMultipliers[] = {0x6c50b47cu, 0xb82f1e52u, 0xc7afe638u, 0x8d22f6e6u};

uint32_t laineKarrasPermutation(uint32_t x, uint32_t seed) {
  x += seed;
  for (uint32_t multiplier : kLaineKarrasMultipliers) x ^= x * multiplier;
  return x;
}

// The reversed coordinate of dimension d (< 4) of the point whose reversed index is `shuffled`.
uint32_t reversedSobolCoordinate(uint32_t d, uint32_t shuffled) {
  const auto& t = kReversedByteTables[d];
  return t[0][shuffled & 0xffu] ^ t[1][(shuffled >> 8) & 0xffu] ^ t[2][(shuffled >> 16) & 0xffu] ^
         t[3][shuffled >> 24];
}

// Eight 32-bit lanes (GCC's vector extension: the operators act lane by lane).
typedef uint32_t U32x8 __attribute__((vector_size(32)));
typedef int32_t I32x8 __attribute__((vector_size(32)));
typedef float F32x8 __attribute__((vector_size(32)));

// laineKarrasPermutation and reverseBits on eight lanes, in place. (By reference: passing 32-byte
// vectors by value would depend on whether the caller was compiled for AVX. Always inlined: they
// take the instruction set of the version they are inlined into.)
[[gnu::always_inline]] inline void laineKarrasPermutation8(U32x8& x, const U32x8& seed) {
  x += seed;
  for (uint32_t multiplier : kLaineKarrasMultipliers) x ^= x * multiplier;
}

[[gnu::always_inline]] inline void reverseBits8(U32x8& x) {
  x = (x << 16) | (x >> 16);
  x = ((x & 0x00ff00ffu) << 8) | ((x & 0xff00ff00u) >> 8);
  x = ((x & 0x0f0f0f0fu) << 4) | ((x & 0xf0f0f0f0u) >> 4);
  x = ((x & 0x33333333u) << 2) | ((x & 0xccccccccu) >> 2);
  x = ((x & 0x55555555u) << 1) | ((x & 0xaaaaaaaau) >> 1);
}

// The body of owenScrambledSobolFloats8, compiled into each of the two versions below (inlining
// gives it their instruction sets).
[[gnu::always_inline]] inline void sobolFloats8(uint32_t reversedIndex,
                                                const uint32_t shuffleSeeds[2],
                                                const uint32_t valueSeeds[8], float values[8]) {
  const uint32_t shuffled0 = laineKarrasPermutation(reversedIndex, shuffleSeeds[0]);
  const uint32_t shuffled1 = laineKarrasPermutation(reversedIndex, shuffleSeeds[1]);
  // The table lookups stay scalar (a gather is no faster); the rest is lane by lane.
  U32x8 bits = {reversedSobolCoordinate(0, shuffled0), reversedSobolCoordinate(1, shuffled0),
                reversedSobolCoordinate(2, shuffled0), reversedSobolCoordinate(3, shuffled0),
                reversedSobolCoordinate(0, shuffled1), reversedSobolCoordinate(1, shuffled1),
                reversedSobolCoordinate(2, shuffled1), reversedSobolCoordinate(3, shuffled1)};
  U32x8 seeds;
  std::memcpy(&seeds, valueSeeds, sizeof seeds);
  laineKarrasPermutation8(bits, seeds);
  reverseBits8(bits);
  // toUnitFloat: the top 24 bits, exact in a float and in a signed int (whose conversion to float
  // is one instruction; the unsigned one is not).
  const I32x8 top24 = __builtin_convertvector(bits >> 8, I32x8);
  const F32x8 unit = __builtin_convertvector(top24, F32x8) * 0x1p-24f;
  std::memcpy(values, &unit, sizeof unit);
}

}  // namespace

uint32_t sobolSample(uint32_t index, uint32_t dimension) {
  assert(dimension < kSobolDimensions);
  const Matrix& columns = kMatrices[dimension];
  uint32_t x = 0;
  for (uint32_t k = 0; index != 0; index >>= 1, ++k) {
    if (index & 1) x ^= columns[k];  // matrix-vector product over GF(2)
  }
  return x;
}

uint32_t nestedUniformScramble(uint32_t x, uint32_t seed) {
  return reverseBits(laineKarrasPermutation(reverseBits(x), seed));
}

void owenScrambledSobolBlock(uint32_t reversedIndex, uint32_t shuffleSeed,
                             const uint32_t valueSeeds[4], uint32_t values[4]) {
  // reverseBits(shuffled index), without reversing twice.
  const uint32_t shuffled = laineKarrasPermutation(reversedIndex, shuffleSeed);
  for (uint32_t d = 0; d < 4; ++d)
    values[d] =
        reverseBits(laineKarrasPermutation(reversedSobolCoordinate(d, shuffled), valueSeeds[d]));
}

void owenScrambledSobolFloats8Portable(uint32_t reversedIndex, const uint32_t shuffleSeeds[2],
                                       const uint32_t valueSeeds[8], float values[8]) {
  sobolFloats8(reversedIndex, shuffleSeeds, valueSeeds, values);
}

// x86 processors with AVX2 get a version of their own; on other processors it is the portable one.
#if defined(__x86_64__) || defined(__i386__)
#define PATHWAY_TARGET_AVX2 __attribute__((target("avx2")))
#else
#define PATHWAY_TARGET_AVX2
#endif

PATHWAY_TARGET_AVX2 void owenScrambledSobolFloats8Avx2(uint32_t reversedIndex,
                                                       const uint32_t shuffleSeeds[2],
                                                       const uint32_t valueSeeds[8],
                                                       float values[8]) {
  sobolFloats8(reversedIndex, shuffleSeeds, valueSeeds, values);
}

bool processorHasAvx2() {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_cpu_init();  // (needed only before main, harmless after)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

void owenScrambledSobolFloats8(uint32_t reversedIndex, const uint32_t shuffleSeeds[2],
                               const uint32_t valueSeeds[8], float values[8]) {
  // Chosen on the first call.
  static const auto version =
      processorHasAvx2() ? owenScrambledSobolFloats8Avx2 : owenScrambledSobolFloats8Portable;
  version(reversedIndex, shuffleSeeds, valueSeeds, values);
}

}  // namespace pathway
