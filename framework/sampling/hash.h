// Integer hashing: turns a tuple such as (pixel x, pixel y, sample index, seed) into well-mixed
// bits, so samplers can be pure functions of their arguments instead of carrying state around.
#pragma once

#include <cstdint>

namespace pathway {

// The splitmix64 finalizer (Steele, Lea & Flood 2014): a bijection on 64-bit integers in which
// every input bit flips each output bit with probability close to 1/2.
inline uint64_t mix64(uint64_t x) {
  x ^= x >> 30;
  x *= 0xbf58476d1ce4e5b9ull;
  x ^= x >> 27;
  x *= 0x94d049bb133111ebull;
  x ^= x >> 31;
  return x;
}

// Folds one more value into a running hash. The multiply by an odd constant keeps it a bijection
// in `value` for a fixed `hash`, and makes the order matter: (a, b) and (b, a) hash differently.
inline uint64_t hashCombine(uint64_t hash, uint64_t value) {
  return mix64(hash * 0x9e3779b97f4a7c15ull + value);
}

// hashValues(a, b, c, ...): one 64-bit hash of any number of integers, order-sensitive.
template <typename... Rest>
uint64_t hashValues(uint64_t first, Rest... rest) {
  uint64_t hash = mix64(first + 0x9e3779b97f4a7c15ull);
  ((hash = hashCombine(hash, static_cast<uint64_t>(rest))), ...);  // C++17 fold: once per value
  return hash;
}

}  // namespace pathway
