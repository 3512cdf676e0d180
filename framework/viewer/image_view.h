// The image side of the window: where the panes are, what is drawn on them (the render, its
// counters, unfinished TODOs, the false-colour legend), and the mouse driving the camera.
// Everything is drawn through ImGui's background draw list, so both GL backends draw it alike.
#pragma once

#include <imgui.h>

#include "viewer/gl_display.h"
#include "viewer/orbit_camera.h"
#include "viewer/render_worker.h"
#include "viewer/viewer_state.h"

namespace pathway {

struct Pane {
  ImVec2 min, max;  // ImGui coordinates
  float width() const { return max.x - min.x; }
  float height() const { return max.y - min.y; }
  bool contains(ImVec2 p) const {
    return p.x >= min.x && p.x < max.x && p.y >= min.y && p.y < max.y;
  }
};

struct ImageLayout {
  Pane panes[2];
  int count = 1;
  int renderWidth = 1, renderHeight = 1;  // pixels each pane's render should have
};

// The panes fill the window right of the panel; renders follow their size in framebuffer pixels
// (divided by the resolution setting) unless the state fixes the size.
ImageLayout layoutPanes(const ViewerState& state, float panelWidth);

// What a pane shows besides the image.
struct PaneInfo {
  const LaneFrame* frame = nullptr;
  DisplayMode mode = DisplayMode::Color;
  float scaleMax = 0.0f;
  const char* side = nullptr;  // "left" / "right" in the split view
  // The grader's signed-z heatmap over the image, and its verdict (empty: none shown).
  const GlTexture* gradeOverlay = nullptr;
  std::vector<std::string> gradeLines;
  bool gradePassed = false;
};

void drawPane(const Pane& pane, const GlTexture& texture, const PaneInfo& info);

// Left drag orbits, right or middle drag pans, the wheel zooms, when the mouse is on a pane and
// not on the panel. Returns true when the camera moved.
class CameraMouse {
 public:
  bool update(const ImageLayout& layout, OrbitCamera& camera);

 private:
  bool dragging_[3] = {false, false, false};
  float paneHeight_ = 1.0f;
};

}  // namespace pathway
