// What a stage hands on to the stages after it. Stages build on each other as in the lecture:
// stage 2's cosine-weighted hemisphere sampling and AO estimate serve stages 3-5, and each variant
// (student or reference) uses its own earlier stages. Stage 1's filters and splat are handed on the
// same way through film/pixel_filter.h.
#pragma once

#include "core/math.h"
#include "core/variant.h"
#include "render/integrator.h"

namespace pathway {

struct StageKit {
  // Stage 2: a direction in the local frame (z along the normal) with density cos θ / π ...
  Vec3 (*sampleCosineHemisphere)(Vec2 u) = nullptr;
  // ... that density, per unit solid angle, for a direction with the given cos θ.
  float (*cosineHemispherePdf)(float cosTheta) = nullptr;
  // Stage 2: one AO direction from `u`, traced up to `distance`: V·cos θ / (π·pdf).
  float (*ambientOcclusionSample)(RenderContext& context, const SurfaceHit& hit, Vec2 u,
                                  float distance) = nullptr;
};

// The kit of `variant`; stage files fill theirs in when they register.
StageKit& stageKit(Variant variant);

}  // namespace pathway
