// FNV-1a: a small hash that is the same in every run and on every machine of one endianness, for
// cache keys and file names (a scene's content, a chart run's description, a cached reference).
// Not for anything an adversary chooses.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace pathway {

class StableHash {
 public:
  void addBytes(const void* data, size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < size; ++i) value_ = (value_ ^ bytes[i]) * 0x100000001b3ull;
  }
  template <typename T>
  void add(const T* data, size_t count) {
    addBytes(data, count * sizeof(T));
  }
  template <typename T>
  void add(const T& value) {
    addBytes(&value, sizeof(T));
  }
  uint64_t value() const { return value_; }

 private:
  uint64_t value_ = 0xcbf29ce484222325ull;
};

inline uint64_t stableHash(std::string_view text) {
  StableHash hash;
  hash.addBytes(text.data(), text.size());
  return hash.value();
}

}  // namespace pathway
