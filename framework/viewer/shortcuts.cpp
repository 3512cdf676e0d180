#include "viewer/shortcuts.h"

#include <imgui.h>

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
    {"T", "toggle yours / reference, the one the other pane shows (Shift+T: right pane)"},
    {"1 ... 5", "stage 1 ... 5 (Shift: right pane)"},
    {"D", "display: colour, variance, rays per sample"},
    {"G", "grade the image against the reference; shows where it differs (again: hide)"},
    {"M", "make a reference for the error plot (relMSE against time); again: cancel"},
    {"+ / -", "exposure up / down one stop"},
    {"Up / Down", "recursion depth of stages 4 and 5 one deeper / shallower (both panes)"},
    {"[ / ]", "lights half / twice as large, at the same power"},
    {"V", "split view on / off"},
    {"B", "split view: equal time / equal ray count"},
    {"Space", "pause / resume rendering"},
    {"F12", "screenshot of the window (pathway_view_screenshot.png)"},
    {"Esc", "close this help"},
};

}  // namespace

ShortcutEffects handleShortcuts(ViewerState& state, const std::vector<KeyPress>& presses) {
  if (ImGui::GetIO().WantCaptureKeyboard) return {};  // typing in a text field
  return applyKeyPresses(state, presses);
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
