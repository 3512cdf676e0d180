// Key presses as they happen, for the frame loop to act on. Polling which keys are down once per
// frame loses a tap that is pressed and released between two frames (2 of 7 quick taps at 4-10
// frames/s); GLFW's key callback sees every press, so the window queues them here and each frame
// drains the queue. Header-only and GL-free, so the tests can drive it without a window.
#pragma once

#ifndef GLFW_INCLUDE_NONE
#define GLFW_INCLUDE_NONE  // no GL header: the viewer loads its GL functions itself
#endif
#include <GLFW/glfw3.h>  // key, action and modifier codes only

#include <utility>
#include <vector>

namespace pathway {

struct KeyPress {
  int key = 0;  // a GLFW key code
  bool shift = false;
};

// Filled and drained on the thread that runs GLFW's event loop (GLFW calls back from
// glfwWaitEvents*), so it needs no lock.
class KeyQueue {
 public:
  // GLFW's key callback arguments. Only presses count: a held key's repeats would step through
  // the displays or exposure faster than anyone reads them, and releases carry no action.
  void onKey(int key, int action, int mods) {
    if (action == GLFW_PRESS && key != GLFW_KEY_UNKNOWN)
      presses_.push_back({key, (mods & GLFW_MOD_SHIFT) != 0});
  }
  // Every press since the last call, oldest first; each press is returned once.
  std::vector<KeyPress> take() { return std::exchange(presses_, {}); }

 private:
  std::vector<KeyPress> presses_;
};

}  // namespace pathway
