// Keyboard shortcuts: one table, read by the handler and by the help overlay (H or F1).
#pragma once

#include "viewer/viewer_state.h"

namespace pathway {

struct ShortcutEffects {
  bool resetCamera = false;
  bool screenshot = false;
  bool grade = false;          // grade the left pane's image against the reference (again: hide it)
  bool makeReference = false;  // make the error plot's reference (again: cancel it)
};

// Applies the keys pressed this frame (unless a text field has the keyboard).
ShortcutEffects handleShortcuts(ViewerState& state);
// The help overlay, centred over the whole window; closes with H, F1, Esc or its button.
void drawHelp(ViewerState& state);

}  // namespace pathway
