// The reference of the stage a pane shows, rendered at the pane's view, settings and parameters:
// what grading (key G) compares with, and what "Make reference" (key M) gives the error plot.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "engine/render_session.h"
#include "render/integrator_registry.h"
#include "viewer/loaded_scene.h"
#include "viewer/render_worker.h"

namespace pathway {

// The reference integrator of `integrator`'s stage, or null when there is none (not a course
// stage, or a handout whose reference library was refused).
const IntegratorInfo* stageReferenceOf(const std::string& integrator);
// Why stageReferenceOf(integrator) is null, in a sentence: "no reference of stage2 here (...)".
std::string missingReferenceOf(const std::string& integrator);

// The seed of a reference made for a pane with `seed`: its samples are not the pane's.
uint64_t referenceSeed(uint64_t seed);

// Renders stageN@ref for `frame` with `spp` samples per pixel, `samplesPerPass` at a time, and
// referenceSeed(the frame's seed). Blocking: run it off the UI thread.
// Returns nothing when `cancel` became true; throws PathwayError when there is no reference.
std::optional<RenderResult> renderStageReference(
    const LaneFrame& frame, const LoadedScene& scene, uint32_t spp, uint32_t samplesPerPass,
    const std::function<void(const RenderStats&)>& onPass = {},
    const std::atomic<bool>* cancel = nullptr);

}  // namespace pathway
