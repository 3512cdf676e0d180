// The ImGui control panel on the left of the window. It edits ViewerState (any edit that changes
// the image restarts the render, see viewer_app.cpp) and reports button presses as actions.
// Integrator choices and parameter widgets are built from the registry: nothing here is per stage.
#pragma once

#include <memory>
#include <string>

#include "viewer/error_plot.h"
#include "viewer/render_worker.h"
#include "viewer/viewer_state.h"

namespace pathway {

// Text the panel edits and messages it shows.
struct PanelText {
  std::string sceneInput;  // the path in the "Scene" field
  std::string sceneMessage;
  bool sceneFailed = false;
  std::string savePrefix = "pathway_view";
  std::string saveMessage;
  bool saveFailed = false;
};

// The error plot's reference, and the one Make reference is rendering.
struct ReferenceStatus {
  std::string source;  // what the plot measures against; empty: no reference
  bool making = false;
  std::string makingIntegrator;  // while making: stageN@ref, at sppDone of sppTarget
  uint32_t sppDone = 0, sppTarget = 0;
  std::string error;  // the last Make reference could not start or failed
};

// What the panel shows but does not edit.
struct PanelStatus {
  std::shared_ptr<const LaneFrame> frames[2];
  float scaleMax[2] = {0.0f, 0.0f};  // of the false-colour displays
  bool idle = true;
  double passSeconds = 0.0;
  float uiFramesPerSecond = 0.0f;
  bool sceneLoading = false;
  bool fixedSize = false;
  const ErrorHistory* errors[2] = {nullptr, nullptr};
  ReferenceStatus reference;
};

enum class PanelAction {
  None,
  OpenScene,
  ResizeLights,  // load the scene again with the light size the widget set
  SaveExr,
  SavePng,
  Screenshot,
  ResetCamera,
  Grade,
  MakeReference  // or cancel the one being made
};

constexpr float kPanelWidth = 380.0f;

PanelAction drawPanel(ViewerState& state, PanelText& text, const PanelStatus& status);

// The last item's help, shown while the mouse is over it.
void tooltip(const std::string& text);

// Parts of the panel (panel_status.cpp): the counters table, and errors and TODOs hit (drawn at
// the top of the panel, where a student cannot miss them).
void counterWidgets(const ViewerState& state, const PanelStatus& status);
void todoWidgets(const ViewerState& state, const PanelStatus& status);
// The reference and the relMSE-against-time plot (panel_error_plot.cpp); true when Make reference
// (or its Cancel) was pressed.
bool errorPlotWidgets(ViewerState& state, const PanelStatus& status);

}  // namespace pathway
