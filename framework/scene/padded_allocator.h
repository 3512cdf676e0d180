// An allocator that leaves 16 spare bytes after every block. Embree reads the last vertex of a
// shared vertex buffer with a 16-byte load, so the mesh's own position array can be handed to it
// directly instead of being copied.
#pragma once

#include <cstddef>
#include <new>

namespace pathway {

template <class T>
struct PaddedAllocator {
  using value_type = T;
  static constexpr std::size_t kSlackBytes = 16;

  PaddedAllocator() = default;
  template <class U>
  PaddedAllocator(const PaddedAllocator<U>&) {}

  T* allocate(std::size_t n) {
    return static_cast<T*>(::operator new(n * sizeof(T) + kSlackBytes));
  }
  void deallocate(T* p, std::size_t) { ::operator delete(p); }

  template <class U>
  bool operator==(const PaddedAllocator<U>&) const {
    return true;
  }
  template <class U>
  bool operator!=(const PaddedAllocator<U>&) const {
    return false;
  }
};

}  // namespace pathway
