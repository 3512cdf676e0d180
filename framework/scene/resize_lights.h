// Lights resized at fixed power: the lecture's point that next-event estimation keeps its noise
// as a light shrinks while paths that must hit the light by chance do not. Used by the viewer's
// "light size" slider and `--light-scale` (setting::kLightScale).
#pragma once

#include "scene/scene.h"

namespace pathway {

// Scales every emissive mesh about the centre of its own bounds by `factor` (each side ×factor,
// area ×factor²) and divides every emissive material's radiance by factor², so each light sends
// the same power into the scene. A light that grows may reach into the geometry around it.
// Call before the scene's bounds are computed. Throws PathwayError for a factor that is not
// positive and finite.
void resizeLights(Scene& scene, float factor);

}  // namespace pathway
