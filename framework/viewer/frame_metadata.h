// The metadata of an image saved from the viewer: what `pathway render` writes, plus the
// viewer's camera, so a saved image says how it was made.
#pragma once

#include "io/image_io.h"
#include "viewer/render_worker.h"

namespace pathway {

RenderMetadata frameMetadata(const LaneFrame& frame);

}  // namespace pathway
