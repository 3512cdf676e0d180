// PCG32 (O'Neill 2014, pcg-random.org): a 64-bit linear congruential state whose output is
// scrambled by an xorshift and a data-dependent rotation (XSH-RR 64/32). Small, fast and
// statistically much better than a bare LCG. This is the reference pcg32_random_r.
#pragma once

#include <cstdint>

namespace pathway {

// 32 random bits -> float in [0, 1). The top 24 bits fill a float's 24-bit significand exactly,
// so every result is a multiple of 2^-24 and the largest is 1 - 2^-24: never 1.0 (a plain
// `bits * 0x1p-32f` would round the largest inputs up to 1.0).
inline float toUnitFloat(uint32_t bits) {
  return static_cast<float>(bits >> 8) * 0x1p-24f;
}

class Pcg32 {
 public:
  // `initState` picks the starting point, `stream` one of 2^63 distinct sequences
  // (pcg32_srandom_r). The defaults are the reference implementation's.
  explicit Pcg32(uint64_t initState = 0x853c49e6748fea9bull,
                 uint64_t stream = 0xda3e39cb94b95bdbull) {
    state_ = 0;
    increment_ = (stream << 1) | 1;  // an LCG increment must be odd for the full 2^64 period
    nextUInt();
    state_ += initState;
    nextUInt();
  }

  uint32_t nextUInt() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + increment_;
    // Output function: xorshift the high bits down, then rotate by the top 5 bits.
    const auto xorShifted = static_cast<uint32_t>(((old >> 18) ^ old) >> 27);
    const auto rotation = static_cast<uint32_t>(old >> 59);
    return (xorShifted >> rotation) | (xorShifted << ((32 - rotation) & 31));
  }

  float nextFloat() { return toUnitFloat(nextUInt()); }

 private:
  uint64_t state_;
  uint64_t increment_;
};

}  // namespace pathway
