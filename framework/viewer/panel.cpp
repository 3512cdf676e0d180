#include "viewer/panel.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "render/integrator_registry.h"
#include "stage_loading/reference_library.h"
#include "viewer/option_widget.h"
#include "viewer/viewer_options.h"

namespace pathway {
namespace {

const ImVec4 kErrorColor(1.0f, 0.35f, 0.35f, 1.0f);
const ImVec4 kGoodColor(0.45f, 0.9f, 0.45f, 1.0f);

std::string integratorLabel(const IntegratorInfo& info) {
  return info.name + (info.variant == Variant::Student ? "   (yours)" : "   (reference)");
}

const IntegratorInfo* findInfo(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return info;
  return nullptr;
}

// One widget per declared parameter (viewer/option_widget.h).
void parameterWidgets(ViewerState& state, int lane, const IntegratorInfo& info) {
  if (info.params.empty()) ImGui::TextDisabled("(no parameters)");
  for (const OptionSpec& spec : info.params) {
    double value = paramValue(state, lane, info, spec);
    if (optionWidget(spec.name.c_str(), spec, value)) setParamValue(state, lane, info, spec, value);
  }
}

void integratorWidgets(ViewerState& state, int lane) {
  ImGui::PushID(lane);
  const IntegratorInfo* current = findInfo(state.integrator[lane]);
  const std::string preview = current ? integratorLabel(*current) : state.integrator[lane];
  if (ImGui::BeginCombo("integrator", preview.c_str())) {
    int lastStage = 0;
    for (const IntegratorInfo* info : allIntegrators()) {
      if (info->stage != lastStage && lastStage != 0) ImGui::Separator();
      lastStage = info->stage;
      const bool selected = current == info;
      if (ImGui::Selectable(integratorLabel(*info).c_str(), selected))
        selectIntegrator(state, lane, info->name);
      tooltip(info->summary);
    }
    ImGui::EndCombo();
  }
  if (current) {
    // The quick switch between the student's version and the reference of the same stage.
    bool isReference = current->variant == Variant::Reference;
    ImGui::BeginDisabled(
        !findStageIntegrator(current->stage, isReference ? Variant::Student : Variant::Reference));
    if (ImGui::RadioButton("yours", !isReference) && isReference) toggleVariant(state, lane);
    ImGui::SameLine();
    if (ImGui::RadioButton("reference", isReference) && !isReference) toggleVariant(state, lane);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::TextDisabled(lane == 0 ? "(key T)" : "(Shift+T)");
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", current->summary.c_str());
    if (current->stage > 0 && !findStageIntegrator(current->stage, Variant::Reference))
      ImGui::TextDisabled("reference stages %s", loadReferenceStages().describe().c_str());
    ImGui::PopTextWrapPos();
    if (current->stage > 1 && !isReference) {
      // Your stage N on the reference's earlier stages: what the grader checks in isolation.
      bool reference = state.earlierStages[lane] == EarlierStages::Reference;
      ImGui::BeginDisabled(!findStageIntegrator(1, Variant::Reference));
      if (ImGui::Checkbox("reference's earlier stages", &reference))
        state.earlierStages[lane] = reference ? EarlierStages::Reference : EarlierStages::Own;
      ImGui::EndDisabled();
      tooltip("On: this stage runs on the reference's stages 1-" +
              std::to_string(current->stage - 1) +
              " (filters, splat, hemisphere sampling), so you see this stage's own effect.");
    }
    parameterWidgets(state, lane, *current);
  }
  ImGui::PopID();
}

void samplingWidgets(ViewerState& state, const PanelStatus& status) {
  RenderSettings& settings = state.settings;
  optionWidget("filter", setting::kFilter, settings.filter);
  optionWidget("filter radius", setting::kFilterRadius, settings.filterRadius,
               settings.filterRadius > 0.0f ? "%.2f px" : "natural");
  optionWidget("sampler", setting::kSampler, settings.sampler);
  if (state.split && state.splitSampler) {
    optionWidget("right sampler", setting::kSampler, *state.splitSampler);
    tooltip("The right pane's own sampler (--split-sampler); 'sampler' above is the left pane's.");
  }
  if (state.split && state.splitFilter) {
    optionWidget("right filter", setting::kFilter, *state.splitFilter);
    tooltip("The right pane's own pixel filter (--split-filter); 'filter' above is the left's.");
  }
  // Typed, not dragged: a seed is a name for a stream of numbers, not a quantity (and 64 bits do
  // not fit the double a slider holds).
  ImGui::InputScalar("seed", ImGuiDataType_U64, &settings.seed);
  tooltip(setting::kSeed.help);
  optionWidget("spp target", kViewerSamplesPerPixel, settings.samplesPerPixel);
  optionWidget("spp per pass", setting::kSamplesPerPass, settings.samplesPerPass);
  if (!status.fixedSize) {
    const char* resolutions[] = {"full", "1/2", "1/4"};
    int index = state.resolutionDivisor == 4 ? 2 : state.resolutionDivisor == 2 ? 1 : 0;
    if (ImGui::Combo("resolution", &index, resolutions, 3)) state.resolutionDivisor = 1 << index;
    tooltip("Render fewer pixels than the pane shows, for speed.");
  }
}

void displayWidgets(ViewerState& state, const PanelStatus& status) {
  int mode = static_cast<int>(state.display);
  ImGui::RadioButton("colour", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("variance", &mode, 1);
  ImGui::SameLine();
  ImGui::RadioButton("rays/sample", &mode, 2);
  state.display = static_cast<DisplayMode>(mode);
  optionWidget("exposure", setting::kExposure, state.exposure, "%+.1f stops");
  if (state.display != DisplayMode::Color) {
    const char* what = state.display == DisplayMode::Variance ? "variance" : "rays per sample";
    ImGui::PushTextWrapPos(0.0f);
    if (state.split)
      ImGui::TextDisabled("%s at the top of the scale (99th percentile): %.4g | %.4g", what,
                          status.scaleMax[0], status.scaleMax[1]);
    else
      ImGui::TextDisabled("%s at the top of the scale (99th percentile): %.4g", what,
                          status.scaleMax[0]);
    ImGui::PopTextWrapPos();
  }
}

void splitWidgets(ViewerState& state) {
  ImGui::Checkbox("split view (key V)", &state.split);
  if (!state.split) return;
  int balance = static_cast<int>(state.balance);
  ImGui::RadioButton("equal time", &balance, 0);
  ImGui::SameLine();
  ImGui::RadioButton("equal ray count", &balance, 1);
  state.balance = static_cast<Balance>(balance);
  if (state.balance == Balance::EqualTime) {
    ImGui::SliderFloat("budget", &state.budgetSeconds, 0.0f, 120.0f,
                       state.budgetSeconds > 0 ? "%.1f s" : "none", ImGuiSliderFlags_AlwaysClamp);
  } else {
    ImGui::SliderFloat("budget", &state.budgetMegaRays, 0.0f, 10000.0f,
                       state.budgetMegaRays > 0 ? "%.0f M rays" : "none",
                       ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_Logarithmic);
  }
  tooltip(
      "Each pane stops here (0: at the spp target). The pane that is behind always gets the "
      "next pass, so both stay level within one pass.");
}

}  // namespace

void tooltip(const std::string& text) {
  if (!text.empty() && ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
  }
}

PanelAction drawPanel(ViewerState& state, PanelText& text, const PanelStatus& status) {
  PanelAction action = PanelAction::None;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0, 0));
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, io.DisplaySize.y));
  ImGui::Begin("Pathway", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoBringToFrontOnFocus);
  ImGui::PushItemWidth(-130.0f);
  ImGui::TextDisabled("H or F1: keys and mouse");
  todoWidgets(state, status);

  if (ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::SetNextItemWidth(-60.0f);
    const bool enter =
        ImGui::InputText("##scene", &text.sceneInput, ImGuiInputTextFlags_EnterReturnsTrue);
    tooltip("A glTF 2.0 file (.gltf or .glb)");
    ImGui::SameLine();
    ImGui::BeginDisabled(status.sceneLoading);
    if (ImGui::Button("Open") || enter) action = PanelAction::OpenScene;
    ImGui::EndDisabled();
    if (status.sceneLoading) ImGui::TextDisabled("loading...");
    if (!text.sceneMessage.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      if (text.sceneFailed)
        ImGui::TextColored(kErrorColor, "%s", text.sceneMessage.c_str());
      else
        ImGui::TextDisabled("%s", text.sceneMessage.c_str());
      ImGui::PopTextWrapPos();
    }
    if (optionWidget("light size", setting::kLightScale, state.sceneOptions.lightScale, "%.3fx"))
      action = PanelAction::ResizeLights;
    if (ImGui::Button("Reset camera (R)")) action = PanelAction::ResetCamera;
  }

  if (ImGui::CollapsingHeader("Integrator", ImGuiTreeNodeFlags_DefaultOpen)) {
    if (ImGui::Button("Grade against the reference (G)")) action = PanelAction::Grade;
    tooltip(
        "Renders the reference of the shown stage at the same view and settings and compares "
        "the left pane with it, tile by tile; the pane then shows where they differ (red: "
        "yours is brighter, blue: darker, yellow outline: significant).");
    if (state.split && ImGui::BeginTabBar("panes")) {
      if (ImGui::BeginTabItem("left pane")) {
        integratorWidgets(state, 0);
        ImGui::EndTabItem();
      }
      if (ImGui::BeginTabItem("right pane")) {
        integratorWidgets(state, 1);
        ImGui::EndTabItem();
      }
      ImGui::EndTabBar();
    } else {
      integratorWidgets(state, 0);
    }
  }
  // Above the counters, which the panes' captions repeat: in a 720-pixel window the plot shows.
  if (ImGui::CollapsingHeader("Error against a reference", ImGuiTreeNodeFlags_DefaultOpen) &&
      errorPlotWidgets(state, status))
    action = PanelAction::MakeReference;
  if (ImGui::CollapsingHeader("Counters", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::Checkbox("paused (Space)", &state.paused);
    counterWidgets(state, status);
  }
  if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen))
    displayWidgets(state, status);
  if (ImGui::CollapsingHeader("Sampling", ImGuiTreeNodeFlags_DefaultOpen))
    samplingWidgets(state, status);
  if (ImGui::CollapsingHeader("Split view", ImGuiTreeNodeFlags_DefaultOpen)) splitWidgets(state);
  if (ImGui::CollapsingHeader("Save", ImGuiTreeNodeFlags_DefaultOpen)) {
    ImGui::InputText("file name", &text.savePrefix);
    tooltip("Without extension; the split view adds -left / -right.");
    if (ImGui::Button("Save EXR")) action = PanelAction::SaveExr;
    tooltip("Linear colour, variance and filter weight, with settings and counters as metadata");
    ImGui::SameLine();
    if (ImGui::Button("Save PNG")) action = PanelAction::SavePng;
    tooltip("sRGB colour with the current exposure");
    ImGui::SameLine();
    if (ImGui::Button("Screenshot")) action = PanelAction::Screenshot;
    tooltip("The whole window, panel included (F12)");
    if (!text.saveMessage.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(text.saveFailed ? kErrorColor : kGoodColor, "%s",
                         text.saveMessage.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  ImGui::PopItemWidth();
  ImGui::End();
  return action;
}

}  // namespace pathway
