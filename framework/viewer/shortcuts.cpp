#include "viewer/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>  // key codes only: ImGui 1.86 indexes keys by the backend's codes
#include <imgui.h>

#include <algorithm>

namespace pathway {
namespace {

struct Shortcut {
  const char* keys;
  const char* action;
};

const Shortcut kShortcuts[] = {
    {"H or F1", "show / hide this help"},
    {"Left drag", "orbit around the scene"},
    {"Right or middle drag", "pan"},
    {"Scroll", "zoom (move closer / further)"},
    {"R", "reset the camera to the scene's camera"},
    {"T", "toggle yours / reference (Shift+T: right pane)"},
    {"1 ... 5", "stage 1 ... 5 (Shift: right pane)"},
    {"D", "display: colour, variance, rays per sample"},
    {"G", "grade the image against the reference; shows where it differs (again: hide)"},
    {"M", "make a reference for the error plot (relMSE against time); again: cancel"},
    {"+ / -", "exposure up / down one stop"},
    {"V", "split view on / off"},
    {"B", "split view: equal time / equal ray count"},
    {"Space", "pause / resume rendering"},
    {"F12", "screenshot of the window (pathway_view_screenshot.png)"},
    {"Esc", "close this help"},
};

bool pressed(int key) {
  // A GLFW key code: ImGui 1.86 indexes keys by it, 1.90 still maps it (its legacy key indices).
  return ImGui::IsKeyPressed(static_cast<ImGuiKey>(key), false);
}

}  // namespace

ShortcutEffects handleShortcuts(ViewerState& state) {
  ShortcutEffects effects;
  const ImGuiIO& io = ImGui::GetIO();
  if (io.WantCaptureKeyboard) return effects;  // typing in a text field
  const int lane = io.KeyShift && state.split ? 1 : 0;
  if (pressed(GLFW_KEY_H) || pressed(GLFW_KEY_F1)) state.showHelp = !state.showHelp;
  if (pressed(GLFW_KEY_ESCAPE)) state.showHelp = false;
  if (pressed(GLFW_KEY_R)) effects.resetCamera = true;
  if (pressed(GLFW_KEY_T)) toggleVariant(state, lane);
  for (int stage = 1; stage <= 5; ++stage)
    if (pressed(GLFW_KEY_0 + stage) || pressed(GLFW_KEY_KP_0 + stage))
      selectStage(state, lane, stage);
  if (pressed(GLFW_KEY_D))
    state.display = static_cast<DisplayMode>((static_cast<int>(state.display) + 1) % 3);
  if (pressed(GLFW_KEY_EQUAL) || pressed(GLFW_KEY_KP_ADD))
    state.exposure = std::min(state.exposure + 1.0f, 10.0f);
  if (pressed(GLFW_KEY_MINUS) || pressed(GLFW_KEY_KP_SUBTRACT))
    state.exposure = std::max(state.exposure - 1.0f, -10.0f);
  if (pressed(GLFW_KEY_V)) state.split = !state.split;
  if (pressed(GLFW_KEY_B))
    state.balance = state.balance == Balance::EqualTime ? Balance::EqualRays : Balance::EqualTime;
  if (pressed(GLFW_KEY_SPACE)) state.paused = !state.paused;
  if (pressed(GLFW_KEY_F12)) effects.screenshot = true;
  if (pressed(GLFW_KEY_G)) effects.grade = true;
  if (pressed(GLFW_KEY_M)) effects.makeReference = true;
  return effects;
}

void drawHelp(ViewerState& state) {
  if (!state.showHelp) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(0.92f);
  if (ImGui::Begin("Keyboard and mouse", &state.showHelp,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoSavedSettings)) {
    if (ImGui::BeginTable("shortcuts", 2, ImGuiTableFlags_RowBg)) {
      for (const Shortcut& shortcut : kShortcuts) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(shortcut.keys);
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(shortcut.action);
      }
      ImGui::EndTable();
    }
    if (ImGui::Button("Close")) state.showHelp = false;
  }
  ImGui::End();
}

}  // namespace pathway
