// The image the error plot measures the panes against: loaded with `pathway view --reference`, or
// made on demand (Make reference, key M). It holds for the view it was made at: another scene,
// camera, pixel filter, image size or parameter that changes the expected image (an AO length, a
// depth: OptionSpec::changesExpectedImage) makes the reference stale.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "film/film.h"
#include "film/pixel_filter.h"
#include "render/parameters.h"
#include "sampling/sampler.h"
#include "viewer/orbit_camera.h"
#include "viewer/render_worker.h"

namespace pathway {

// What decides the expected image besides the integrator.
struct ReferenceView {
  std::string scenePath;
  uint64_t sceneContent = 0;  // the same file with its lights resized is another scene
  CameraPose camera;
  FilterType filter = FilterType::Box;
  float filterRadius = 0.0f;  // in pixels, 0 decoded to the filter's own
  ParamValues params;         // of the integrator that made it (empty: not known)
};

ReferenceView viewOf(const LaneFrame& frame);

struct ReferenceImage {
  Image image;            // linear RGB
  std::string source;     // for the panel: "ref.exr (stage5@ref, 4096 spp)", "stage5@ref, 1024 spp"
  bool fromFile = false;  // loaded with --reference, not made in the viewer
  ReferenceView view;     // the view it shows
  // Its random numbers, when known: a pane with the same ones draws the reference's own samples,
  // and its error would fall to 0 at the reference's spp instead of as 1/time.
  std::optional<uint64_t> seed;
  std::optional<SamplerType> sampler;
};

// Reads an EXR file (`pathway render` writes them); throws PathwayError naming the file when it
// is missing, malformed, not an EXR or holds non-finite values. `view` is the view it is for.
ReferenceImage loadReference(const std::string& path, const ReferenceView& view);

// Why `frame` cannot be measured against `reference` (another size, a stale view, the same
// random numbers), in one sentence for the panel; empty when it can.
std::string referenceProblem(const ReferenceImage& reference, const LaneFrame& frame);

}  // namespace pathway
