// The viewer's first state, from its options (the command line, or a lecture demo): GL-free, so
// the tests start a demo exactly as `pathway view --demo` does.
#pragma once

#include "viewer/viewer_options.h"
#include "viewer/viewer_state.h"

namespace pathway {

// The state the options describe; throws PathwayError on unknown names or bad parameters.
ViewerState initialState(const ViewerOptions& options);

// With one side of the render size given (--width or --height, or a demo's width), the other
// from the scene camera's aspect ratio, as `pathway render` does.
void completeRenderSize(ViewerState& state, const Scene& scene);

}  // namespace pathway
