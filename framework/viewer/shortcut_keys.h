// What each shortcut key does to the viewer's state: the dispatch from a queued key press
// (key_queue.h) to its action. Header-only and GL-free, so the tests run it without a window; the
// help overlay's table (shortcuts.cpp) lists the same keys.
#pragma once

#include <algorithm>
#include <vector>

#include "viewer/key_queue.h"
#include "viewer/viewer_state.h"

namespace pathway {

// What the frame does beyond the state: the actions that need the viewer itself.
struct ShortcutEffects {
  bool resetCamera = false;
  bool screenshot = false;
  bool grade = false;          // grade the left pane's image against the reference (again: hide it)
  bool makeReference = false;  // make the error plot's reference (again: cancel it)
  bool resizeLights = false;   // the light size changed: load the scene again
};

// Acts on one press; Shift sends the pane keys (T, 1-5) to the right pane in the split view.
inline void applyKeyPress(ViewerState& state, const KeyPress& press, ShortcutEffects& effects) {
  const int lane = press.shift && state.split ? 1 : 0;
  const int key = press.key;
  if (key == GLFW_KEY_H || key == GLFW_KEY_F1) state.showHelp = !state.showHelp;
  if (key == GLFW_KEY_ESCAPE) state.showHelp = false;
  if (key == GLFW_KEY_R) effects.resetCamera = true;
  if (key == GLFW_KEY_T) toggleVariant(state, lane);
  for (int stage = 1; stage <= 5; ++stage)
    if (key == GLFW_KEY_0 + stage || key == GLFW_KEY_KP_0 + stage) selectStage(state, lane, stage);
  if (key == GLFW_KEY_D)
    state.display = static_cast<DisplayMode>((static_cast<int>(state.display) + 1) % 3);
  if (key == GLFW_KEY_EQUAL || key == GLFW_KEY_KP_ADD)
    state.exposure = std::min(state.exposure + 1.0f, 10.0f);
  if (key == GLFW_KEY_MINUS || key == GLFW_KEY_KP_SUBTRACT)
    state.exposure = std::max(state.exposure - 1.0f, -10.0f);
  if (key == GLFW_KEY_V) state.split = !state.split;
  if (key == GLFW_KEY_B)
    state.balance = state.balance == Balance::EqualTime ? Balance::EqualRays : Balance::EqualTime;
  if (key == GLFW_KEY_SPACE) state.paused = !state.paused;
  if (key == GLFW_KEY_F12) effects.screenshot = true;
  if (key == GLFW_KEY_G) effects.grade = true;
  if (key == GLFW_KEY_M) effects.makeReference = true;
  if (key == GLFW_KEY_UP) stepRecursionDepth(state, 1);
  if (key == GLFW_KEY_DOWN) stepRecursionDepth(state, -1);
  if (key == GLFW_KEY_LEFT_BRACKET && scaleLightSize(state, 0.5f)) effects.resizeLights = true;
  if (key == GLFW_KEY_RIGHT_BRACKET && scaleLightSize(state, 2.0f)) effects.resizeLights = true;
}

// Acts on every press, in the order they came.
inline ShortcutEffects applyKeyPresses(ViewerState& state, const std::vector<KeyPress>& presses) {
  ShortcutEffects effects;
  for (const KeyPress& press : presses) applyKeyPress(state, press, effects);
  return effects;
}

}  // namespace pathway
