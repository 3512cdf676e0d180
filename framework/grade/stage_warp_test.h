// A stage's warp test as `pathway warptest` and the grader run it: the sampling routine the stage
// writes on its own, tested against the density it claims. Stage 2: the hemisphere directions
// against their pdf (grade/warp_fit.h). Stage 5: the points on the emitters against their pdfArea
// (grade/light_sampling_fit.h) on kWarpTestScene, with the emitters picked by area and by power.
#pragma once

#include <cstdint>
#include <string>

#include "core/variant.h"
#include "grade/warp_fit.h"
#include "scene/scene.h"

namespace pathway {

// Stage 5's emitters: three lights of different sizes and strengths (six triangles).
constexpr const char* kWarpTestScene = "grading_lights.gltf";
// What the grader draws (and `pathway warptest` by default): 12 ms for stage 2, 20 for stage 5.
constexpr int kWarpTestSamples = 200000;

struct StageWarpTest {
  bool passed = false;
  double p = 1.0;             // the smallest p of its χ² tests
  std::string verdict;        // one line per test ("light-pick area: ...")
  WarpTestResult hemisphere;  // stage 2's counts, for a picture
};

// Whether `stage` writes a sampling routine of its own that has a warp test (stages 2 and 5).
bool hasWarpTest(int stage);

// Runs `stage`'s warp test on `variant`'s routine, as registered in this process. `lights` is
// kWarpTestScene loaded (stage 5 only). Throws PathwayError for a stage without a warp test, or
// when the stage is not there.
StageWarpTest runStageWarpTest(int stage, Variant variant, const Scene* lights, int samples,
                               uint64_t seed, bool keepDirections = false);

}  // namespace pathway
