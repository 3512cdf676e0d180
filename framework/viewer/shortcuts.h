// Keyboard shortcuts: the frame's handler (the queued presses, acted on as shortcut_keys.h says)
// and the help overlay listing them (H or F1).
#pragma once

#include <vector>

#include "viewer/shortcut_keys.h"
#include "viewer/viewer_state.h"

namespace pathway {

// Applies the keys pressed since the last frame (key_queue.h), unless a text field has the
// keyboard: then they were typed into it.
ShortcutEffects handleShortcuts(ViewerState& state, const std::vector<KeyPress>& presses);
// The help overlay, centred over the whole window; closes with H, F1, Esc or its button.
void drawHelp(ViewerState& state);

}  // namespace pathway
