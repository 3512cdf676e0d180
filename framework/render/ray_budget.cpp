#include "render/ray_budget.h"

#include <limits>

#include "core/error.h"

namespace pathway {

uint64_t naiveRecursionRaysPerSample(uint64_t branching, uint64_t depth) {
  constexpr uint64_t kMax = std::numeric_limits<uint64_t>::max();
  uint64_t total = 0, level = 1;  // level = N^k, the rays cast at bounce k
  for (uint64_t k = 0; k <= depth; ++k) {
    if (total > kMax - level) return kMax;
    total += level;
    if (k < depth) {
      if (branching != 0 && level > kMax / branching) return kMax;
      level *= branching;
    }
  }
  return total;
}

void checkRayBudget(const std::string& integrator, uint64_t branching, uint64_t depth,
                    uint64_t budget) {
  const uint64_t rays = naiveRecursionRaysPerSample(branching, depth);
  if (rays <= budget) return;
  const std::string count =
      rays == std::numeric_limits<uint64_t>::max() ? "more than 1.8e19" : std::to_string(rays);
  throw PathwayError(integrator + ": branching " + std::to_string(branching) + " to depth " +
                     std::to_string(depth) + " casts " + count +
                     " rays per camera sample (1 + N + ... + N^depth), over the budget of " +
                     std::to_string(budget) +
                     " (parameter max-rays). This is the lecture's "
                     "combinatorial explosion: lower branching or depth, or raise max-rays.");
}

}  // namespace pathway
