// References for the error plot, kept on disk between runs: a lecture demo's plot should not wait
// minutes for a 1024-spp reference rendered in class. `pathway view --prepare-demos` makes every
// demo's reference once; a demo that asks for its reference (Make reference, M) then loads it in
// milliseconds. An entry is found only for exactly the same expected image: the key covers the
// scene's content, the camera, the image size, the filter, the reference integrator and its
// parameters, the sampler, seed and spp (and the file records the key, so a hash collision reads
// as a miss).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "viewer/loaded_scene.h"
#include "viewer/reference_image.h"
#include "viewer/render_worker.h"

namespace pathway {

// $XDG_CACHE_HOME/pathway/references, else ~/.cache/pathway/references (the XDG default).
std::filesystem::path referenceCacheFolder();

// Everything that decides the reference made for `frame` at `spp`, as one line of text.
std::string referenceCacheKey(const LaneFrame& frame, const LoadedScene& scene, uint32_t spp);

// The cached reference for `frame` at `spp`, if `folder` holds one; a damaged entry is a miss.
std::optional<ReferenceImage> loadCachedReference(const std::filesystem::path& folder,
                                                  const LaneFrame& frame, const LoadedScene& scene,
                                                  uint32_t spp);

// Keeps `reference`, made for `frame` at `spp`, in `folder` (created if missing). Written through
// a temporary file, so a reader never sees half an entry. Throws PathwayError naming the file.
void storeCachedReference(const std::filesystem::path& folder, const LaneFrame& frame,
                          const LoadedScene& scene, uint32_t spp, const ReferenceImage& reference);

}  // namespace pathway
