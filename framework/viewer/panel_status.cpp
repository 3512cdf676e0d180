// The read-only parts of the panel: live counters per pane, and what keeps a pane from being
// finished (errors, TODOs hit in the stage code).
#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

#include "core/number_format.h"
#include "viewer/panel.h"

namespace pathway {
namespace {

const ImVec4 kTodoColor(1.0f, 0.62f, 0.15f, 1.0f);
const ImVec4 kErrorColor(1.0f, 0.35f, 0.35f, 1.0f);
const ImVec4 kGoodColor(0.45f, 0.9f, 0.45f, 1.0f);

std::string millions(uint64_t n) {
  return formatNumber("%.2f M", static_cast<double>(n) * 1e-6);
}

using CounterRows = std::vector<std::pair<const char*, std::string>>;

CounterRows counterRows(const LaneFrame& frame) {
  const RenderStats& s = frame.stats;
  const RayCounters& c = s.counters;
  CounterRows rows = {
      {"spp",
       std::to_string(s.samplesPerPixel) + " / " + std::to_string(frame.settings.samplesPerPixel)},
      {"render time", formatNumber("%.2f s", s.seconds)},
      {"rays / s", formatNumber("%.1f M", s.seconds > 0 ? c.totalRays() / s.seconds * 1e-6 : 0.0)},
      {"primary rays", millions(c.primary)},
      {"secondary rays", millions(c.secondary)},
      {"shadow rays", millions(c.shadow)},
      {"total rays", millions(c.totalRays())},
      {"invalid samples", std::to_string(c.invalidSamples)},
      {"pixels with sum w = 0", std::to_string(frame.unresolvedPixels)},
      {"first image after", formatNumber("%.0f ms", frame.firstImageSeconds * 1e3)},
      {"image",
       std::to_string(frame.settings.width) + " x " + std::to_string(frame.settings.height)},
  };
  return rows;
}

}  // namespace

void counterWidgets(const ViewerState& state, const PanelStatus& status) {
  const int lanes = state.split ? 2 : 1;
  bool failed = false;
  for (int lane = 0; lane < lanes; ++lane)
    failed = failed || (status.frames[lane] && !status.frames[lane]->error.empty());
  if (status.idle)
    ImGui::TextColored(kGoodColor, "%s",
                       state.paused ? "paused (Space)"
                       : failed     ? "stopped: see the error above"
                                    : "done");
  else if (status.passSeconds > 0.5)
    ImGui::Text("rendering... this pass has run %.1f s", status.passSeconds);
  else
    ImGui::Text("rendering...");
  if (status.uiFramesPerSecond > 0.0f) {
    ImGui::SameLine();
    ImGui::TextDisabled("  UI %.0f fps", status.uiFramesPerSecond);
  }

  // One row per counter, one column per pane.
  CounterRows rows[2];
  for (int lane = 0; lane < lanes; ++lane)
    if (status.frames[lane] && status.frames[lane]->error.empty())
      rows[lane] = counterRows(*status.frames[lane]);
  if (rows[0].empty() && rows[lanes - 1].empty()) {
    ImGui::TextDisabled(failed ? "no image" : "waiting for the first image...");
    return;
  }
  if (!ImGui::BeginTable("counters", 1 + lanes,
                         ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg))
    return;
  if (lanes == 2) {
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn("left");
    ImGui::TableSetupColumn("right");
    ImGui::TableHeadersRow();
  }
  const CounterRows& names = rows[0].empty() ? rows[1] : rows[0];
  for (size_t i = 0; i < names.size(); ++i) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(names[i].first);
    for (int lane = 0; lane < lanes; ++lane) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(rows[lane].empty() ? "-" : rows[lane][i].second.c_str());
    }
  }
  ImGui::EndTable();
}

void todoWidgets(const ViewerState& state, const PanelStatus& status) {
  for (int lane = 0; lane < (state.split ? 2 : 1); ++lane) {
    const LaneFrame* frame = status.frames[lane].get();
    if (!frame) continue;
    if (!frame->error.empty()) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kErrorColor, "%s cannot render: %s", frame->integrator.c_str(),
                         frame->error.c_str());
      ImGui::PopTextWrapPos();
    }
    for (const TodoRecord& todo : frame->todos) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(kTodoColor, "TODO not done: %s:%d", todo.file.c_str(), todo.line);
      ImGui::TextDisabled("  %s", todo.task.c_str());
      ImGui::PopTextWrapPos();
    }
  }
}

}  // namespace pathway
