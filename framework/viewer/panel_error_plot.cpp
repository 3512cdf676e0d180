// The panel's error section: the reference (loaded, or made with Make reference), and relMSE
// against render time for each pane on log-log axes drawn with ImDrawList (ImGui's own plots have
// no log axes), with a slope −1 guide: the rate at which Monte Carlo error falls.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "core/number_format.h"
#include "viewer/option_widget.h"
#include "viewer/panel.h"

namespace pathway {
namespace {

const ImVec4 kErrorColor(1.0f, 0.35f, 0.35f, 1.0f);
const ImVec4 kStaleColor(1.0f, 0.62f, 0.15f, 1.0f);
const ImVec4 kLaneColor[2] = {ImVec4(1.0f, 0.58f, 0.2f, 1.0f), ImVec4(0.35f, 0.72f, 1.0f, 1.0f)};
const ImU32 kPlotBackground = IM_COL32(22, 22, 26, 255);
const ImU32 kGridColor = IM_COL32(70, 70, 78, 255);
const ImU32 kGuideColor = IM_COL32(170, 170, 170, 200);
const ImU32 kLabelColor = IM_COL32(160, 160, 168, 255);

constexpr float kPlotHeight = 170.0f;
constexpr float kMarginLeft = 38.0f;  // the relMSE labels
constexpr float kMarginBottom = 17.0f;
constexpr float kMarginTop = 4.0f;
constexpr float kMarginRight = 18.0f;  // room for the last seconds label to centre on its tick
constexpr int kMaxLabels = 6;          // per axis; more decades label every other one

// Every `step`-th decade gets a label, so labels never overlap.
int labelStep(const LogAxis& axis) {
  return (axis.last - axis.first + kMaxLabels - 1) / kMaxLabels;
}

bool measurable(const ErrorPoint& point) {
  return point.seconds > 0.0 && point.relMse > 0.0;  // log axes
}

void drawPlot(const ErrorHistory* const* histories, int lanes) {
  double xLo = std::numeric_limits<double>::max(), xHi = 0.0;
  double yLo = std::numeric_limits<double>::max(), yHi = 0.0;
  const ErrorPoint* anchor = nullptr;  // the guide goes through the first point
  for (int lane = 0; lane < lanes; ++lane)
    for (const ErrorPoint& point : histories[lane]->points()) {
      if (!measurable(point)) continue;
      if (!anchor) anchor = &point;
      xLo = std::min(xLo, point.seconds);
      xHi = std::max(xHi, point.seconds);
      yLo = std::min(yLo, point.relMse);
      yHi = std::max(yHi, point.relMse);
    }
  if (!anchor) return;  // the lines under the plot say why
  const LogAxis x = logAxis(xLo, xHi), y = logAxis(yLo, yHi);

  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::Dummy(ImVec2(width, kPlotHeight));
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 p0(origin.x + kMarginLeft, origin.y + kMarginTop);
  const ImVec2 p1(origin.x + width - kMarginRight, origin.y + kPlotHeight - kMarginBottom);
  auto screenX = [&](double log10Seconds) {
    return p0.x + static_cast<float>((log10Seconds - x.first) / (x.last - x.first)) * (p1.x - p0.x);
  };
  auto screenY = [&](double log10RelMse) {
    return p1.y - static_cast<float>((log10RelMse - y.first) / (y.last - y.first)) * (p1.y - p0.y);
  };
  draw->AddRectFilled(p0, p1, kPlotBackground);

  const float fontSize = ImGui::GetFontSize();
  for (int e = x.first; e <= x.last; ++e) {
    const float sx = screenX(e);
    draw->AddLine(ImVec2(sx, p0.y), ImVec2(sx, p1.y), kGridColor);
    if ((e - x.first) % labelStep(x) != 0) continue;
    const std::string label = secondsLabel(e);
    const float textWidth = ImGui::CalcTextSize(label.c_str()).x;
    const float left = std::clamp(sx - 0.5f * textWidth, origin.x, origin.x + width - textWidth);
    draw->AddText(ImVec2(left, p1.y + 2.0f), kLabelColor, label.c_str());
  }
  for (int e = y.first; e <= y.last; ++e) {
    const float sy = screenY(e);
    draw->AddLine(ImVec2(p0.x, sy), ImVec2(p1.x, sy), kGridColor);
    if ((e - y.first) % labelStep(y) != 0) continue;
    const std::string label = decadeLabel(e);
    const float textWidth = ImGui::CalcTextSize(label.c_str()).x;
    const float top = std::clamp(sy - 0.5f * fontSize, origin.y, p1.y - fontSize);
    draw->AddText(ImVec2(p0.x - textWidth - 4.0f, top), kLabelColor, label.c_str());
  }

  draw->PushClipRect(p0, p1, true);
  // Slope −1 through the first point: log relMSE = log e0 + log t0 − log t, in dashes.
  const double a = std::log10(anchor->relMse) + std::log10(anchor->seconds);
  const int dashes = 40;
  for (int i = 0; i < dashes; i += 2) {
    const double u0 = x.first + (x.last - x.first) * double(i) / dashes;
    const double u1 = x.first + (x.last - x.first) * double(i + 1) / dashes;
    draw->AddLine(ImVec2(screenX(u0), screenY(a - u0)), ImVec2(screenX(u1), screenY(a - u1)),
                  kGuideColor, 1.0f);
  }
  for (int lane = 0; lane < lanes; ++lane) {
    std::vector<ImVec2> line;
    for (const ErrorPoint& point : histories[lane]->points())
      if (measurable(point))
        line.emplace_back(screenX(std::log10(point.seconds)), screenY(std::log10(point.relMse)));
    if (line.empty()) continue;
    const ImU32 color = ImGui::ColorConvertFloat4ToU32(kLaneColor[lane]);
    draw->AddPolyline(line.data(), static_cast<int>(line.size()), color, ImDrawFlags_None, 2.0f);
    draw->AddCircleFilled(line.back(), 3.0f, color);
  }
  draw->PopClipRect();
  draw->AddRect(p0, p1, kGridColor);
  draw->AddText(ImVec2(p0.x + 4.0f, p0.y + 1.0f), kLabelColor, "relMSE");
  const char* guide = "- - slope -1";
  draw->AddText(ImVec2(p1.x - ImGui::CalcTextSize(guide).x - 4.0f, p0.y + 1.0f), kGuideColor,
                guide);
}

// Each pane's newest value, in its line's colour: "left  stage5: 2.31e-3 at 64 spp, 1.20 s",
// then why a pane has none (once, when both panes have the same reason).
void latestValues(const ErrorHistory* const* histories, int lanes) {
  std::vector<std::string> messages;
  for (int lane = 0; lane < lanes; ++lane) {
    const ErrorHistory& history = *histories[lane];
    const std::string name =
        (lanes == 2 ? (lane == 0 ? "left  " : "right  ") : "") + history.integrator();
    ImGui::TextColored(kLaneColor[lane], "%s", name.c_str());
    ImGui::SameLine();
    if (!history.points().empty()) {
      const ErrorPoint& last = history.points().back();
      ImGui::Text("relMSE %s  at %u spp, %.2f s", formatNumber("%.3g", last.relMse).c_str(),
                  last.spp, last.seconds);
    } else {
      ImGui::TextDisabled(history.message().empty() ? "waiting for an image" : "not measured");
    }
    if (!history.message().empty() &&
        std::find(messages.begin(), messages.end(), history.message()) == messages.end())
      messages.push_back(history.message());
  }
  ImGui::PushTextWrapPos(0.0f);
  for (const std::string& message : messages)
    ImGui::TextColored(kStaleColor, "%s", message.c_str());
  ImGui::PopTextWrapPos();
}

}  // namespace

bool errorPlotWidgets(ViewerState& state, const PanelStatus& status) {
  const ReferenceStatus& reference = status.reference;
  bool pressed = false;
  if (reference.making) {
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s: %u / %u spp", reference.makingIntegrator.c_str(),
                  reference.sppDone, reference.sppTarget);
    const float fraction =
        reference.sppTarget > 0 ? float(reference.sppDone) / float(reference.sppTarget) : 0.0f;
    ImGui::ProgressBar(fraction, ImVec2(-90.0f, 0.0f), overlay);
    ImGui::SameLine();
    pressed = ImGui::Button("Cancel (M)");
  } else {
    pressed = ImGui::Button("Make reference (M)");
    tooltip(
        "Renders the reference of the left pane's stage (stageN@ref) at this view and these "
        "settings with 'reference spp' samples per pixel, in the background (pausing the panes, "
        "Space, makes it faster). When it is done the panes start over, so the plot follows them "
        "from their first pass.");
  }
  optionWidget("reference spp", setting::kReferenceSamplesPerPixel, state.referenceSpp);
  ImGui::PushTextWrapPos(0.0f);
  if (!reference.error.empty()) ImGui::TextColored(kErrorColor, "%s", reference.error.c_str());
  if (reference.source.empty()) {
    if (!reference.making)
      ImGui::TextDisabled("No reference: make one, or start with --reference FILE.exr.");
    ImGui::PopTextWrapPos();
    return pressed;
  }
  ImGui::TextDisabled("reference: %s", reference.source.c_str());
  ImGui::PopTextWrapPos();

  const int lanes = state.split ? 2 : 1;
  const ErrorHistory* histories[2] = {status.errors[0], status.errors[1]};
  if (!histories[0] || (lanes == 2 && !histories[1])) return pressed;
  drawPlot(histories, lanes);
  latestValues(histories, lanes);
  return pressed;
}

}  // namespace pathway
