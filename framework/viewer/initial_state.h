// The viewer's first state, from its options (the command line, or a lecture demo): GL-free, so
// the tests start a demo exactly as `pathway view --demo` does.
#pragma once

#include "viewer/viewer_options.h"
#include "viewer/viewer_state.h"

namespace pathway {

// The state the options describe; throws PathwayError on unknown names or bad parameters.
ViewerState initialState(const ViewerOptions& options);

}  // namespace pathway
