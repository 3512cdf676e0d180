// Small scenes built in memory for unit tests, so framework tests do not depend on scene files.
#pragma once

#include <string>

#include "scene/scene.h"

namespace pathway::test {

// Adds a quad p0 p1 p2 p3 (counter-clockwise seen from its front) as its own mesh.
void addQuad(Scene& scene, const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
             uint32_t material);

// A square plane of half-size `halfSize` at height y = 0 facing +y, everything scaled by `scale`
// and moved by (offset, offset, offset). Camera above it, looking down at 45 degrees.
Scene openPlane(float scale, float offset, float halfSize = 100.0f);

// No geometry at all: every camera ray sees the constant `background`.
Scene constantScene(const Color& background);

// A closed box seen from inside with a smaller box in it and an emissive patch on the ceiling:
// edges, occlusion and light for determinism tests.
Scene boxRoom();

// A floor (albedo 0.5, facing up) under a square emitter of side `side` at height 1 facing down,
// with radiance 1 / (π side²) so its power stays 1 as it shrinks. The camera looks at the point
// below the light from (0, 0.6, 1.5); with an odd image size the centre pixel sees that point.
Scene smallLight(float side);

// Finishes a scene built by hand: materials present, bounds computed.
void finishScene(Scene& scene);

}  // namespace pathway::test
