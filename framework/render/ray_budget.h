// Ray counts of naive recursive tracing, computed before rendering so an exploding request can be
// refused with a message instead of running for hours.
#pragma once

#include <cstdint>
#include <string>

namespace pathway {

// Rays per camera sample when every hit spawns `branching` rays down to `depth` bounces:
// 1 + N + N^2 + ... + N^depth = (N^(depth+1) - 1) / (N - 1). Saturates at UINT64_MAX.
uint64_t naiveRecursionRaysPerSample(uint64_t branching, uint64_t depth);

// Throws PathwayError, naming the count and the budget, when the count exceeds `budget`.
void checkRayBudget(const std::string& integrator, uint64_t branching, uint64_t depth,
                    uint64_t budget);

}  // namespace pathway
