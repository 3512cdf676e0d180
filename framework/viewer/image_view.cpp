#include "viewer/image_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "core/number_format.h"
#include "render/integrator_registry.h"

namespace pathway {
namespace {

const ImU32 kTextColor = IM_COL32(235, 235, 235, 255);
const ImU32 kBoxColor = IM_COL32(0, 0, 0, 170);
const ImU32 kTodoBox = IM_COL32(150, 75, 0, 230);
const ImU32 kErrorBox = IM_COL32(150, 20, 20, 235);
const ImU32 kGradePass = IM_COL32(20, 110, 40, 230);

// Lines of text on a translucent box, wrapped at `maxWidth`; `anchor` is the box's top-left, or
// its bottom-left when `growUp`. Returns the box's height.
float textBox(ImDrawList* draw, ImVec2 anchor, const std::vector<std::string>& lines, ImU32 box,
              float maxWidth, bool growUp = false) {
  if (lines.empty()) return 0.0f;
  const float pad = 5.0f, wrap = std::max(maxWidth - 2 * pad, 50.0f);
  float width = 0.0f, height = 0.0f;
  std::vector<float> heights;
  for (const std::string& line : lines) {
    const ImVec2 size = ImGui::CalcTextSize(line.c_str(), nullptr, false, wrap);
    width = std::max(width, size.x);
    heights.push_back(size.y);
    height += size.y;
  }
  height += 2 * pad;
  const ImVec2 min(anchor.x, growUp ? anchor.y - height : anchor.y);
  draw->AddRectFilled(min, ImVec2(min.x + width + 2 * pad, min.y + height), box, 4.0f);
  float y = min.y + pad;
  for (size_t i = 0; i < lines.size(); ++i) {
    draw->AddText(ImGui::GetFont(), ImGui::GetFontSize(), ImVec2(min.x + pad, y), kTextColor,
                  lines[i].c_str(), nullptr, wrap);
    y += heights[i];
  }
  return height;
}

std::string describe(const LaneFrame& frame, bool detailed) {
  std::string text = frame.integrator;
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == frame.integrator)
      text += info->variant == Variant::Student ? "  (yours)" : "  (reference)";
  if (!frame.params.specs().empty()) text += "  " + frame.params.describe();
  if (frame.earlierStages == EarlierStages::Reference) text += "  (stages before: reference)";
  if (detailed)  // the panes may differ in sampler or filter alone (--split-sampler,
                 // --split-filter)
    text += "  sampler " + setting::kSampler.format(static_cast<double>(frame.settings.sampler)) +
            "  filter " + setting::kFilter.format(static_cast<double>(frame.settings.filter));
  return text;
}

std::vector<std::string> counters(const LaneFrame& frame, bool detailed) {
  const RenderStats& s = frame.stats;
  const RayCounters& c = s.counters;
  char line[160];
  std::snprintf(line, sizeof line, "%u/%u spp   %.2f s   %.1f M rays/s", s.samplesPerPixel,
                frame.settings.samplesPerPixel, s.seconds,
                s.seconds > 0 ? c.totalRays() / s.seconds * 1e-6 : 0.0);
  std::vector<std::string> lines = {describe(frame, detailed), line};
  if (detailed) {
    std::snprintf(line, sizeof line, "rays: %.2f M primary, %.2f M secondary, %.2f M shadow",
                  c.primary * 1e-6, c.secondary * 1e-6, c.shadow * 1e-6);
    lines.push_back(line);
    // One primary ray per camera sample: what the ray explosion multiplies.
    if (c.primary > 0) {
      std::snprintf(line, sizeof line, "%.1f rays per camera sample",
                    static_cast<double>(c.totalRays()) / static_cast<double>(c.primary));
      lines.push_back(line);
    }
  }
  if (c.invalidSamples > 0)
    lines.push_back(std::to_string(c.invalidSamples) + " non-finite samples dropped");
  return lines;
}

void legend(ImDrawList* draw, const Pane& pane, const PaneInfo& info) {
  const bool rays = info.mode == DisplayMode::RayHeatmap;
  const char* title =
      rays ? "rays per camera sample (log scale)" : "variance of the pixel estimate";
  const float barWidth = std::max(180.0f, ImGui::CalcTextSize(title).x);
  const float barHeight = 12.0f, margin = 10.0f;
  const ImVec2 min(pane.max.x - barWidth - margin, pane.max.y - barHeight - margin - 20.0f);
  draw->AddRectFilled(ImVec2(min.x - 6, min.y - 22), ImVec2(pane.max.x - 4, pane.max.y - 4),
                      kBoxColor, 4.0f);
  const int steps = 32;
  for (int i = 0; i < steps; ++i) {
    uint8_t a[3], b[3];
    falseColor(static_cast<float>(i) / steps, a);
    falseColor(static_cast<float>(i + 1) / steps, b);
    const float x0 = min.x + barWidth * i / steps, x1 = min.x + barWidth * (i + 1) / steps;
    const ImU32 ca = IM_COL32(a[0], a[1], a[2], 255), cb = IM_COL32(b[0], b[1], b[2], 255);
    draw->AddRectFilledMultiColor(ImVec2(x0, min.y), ImVec2(x1, min.y + barHeight), ca, cb, cb, ca);
  }
  draw->AddText(ImVec2(min.x, min.y - 18), kTextColor, title);
  const std::string top = formatNumber("%.4g", info.scaleMax);
  draw->AddText(ImVec2(min.x, min.y + barHeight + 2), kTextColor, rays ? "1" : "0");
  draw->AddText(
      ImVec2(min.x + barWidth - ImGui::CalcTextSize(top.c_str()).x, min.y + barHeight + 2),
      kTextColor, top.c_str());
}

void drawPaneContent(ImDrawList* draw, const Pane& pane, const GlTexture& texture,
                     const PaneInfo& info) {
  const LaneFrame* frame = info.frame;
  if (texture.width() > 0 && frame) {
    // Fit the image into the pane, keeping its aspect ratio, centred.
    const float scale = std::min(pane.width() / texture.width(), pane.height() / texture.height());
    const ImVec2 size(texture.width() * scale, texture.height() * scale);
    const ImVec2 min(pane.min.x + 0.5f * (pane.width() - size.x),
                     pane.min.y + 0.5f * (pane.height() - size.y));
    draw->AddImage(texture.imguiId(), min, ImVec2(min.x + size.x, min.y + size.y));
    if (info.gradeOverlay)  // translucent, so the image shows through where nothing differs
      draw->AddImage(info.gradeOverlay->imguiId(), min, ImVec2(min.x + size.x, min.y + size.y),
                     ImVec2(0, 0), ImVec2(1, 1), IM_COL32(255, 255, 255, 150));
  }
  const float margin = 8.0f, width = pane.width() - 2 * margin;
  const ImVec2 corner(pane.min.x + margin, pane.min.y + margin);
  if (!frame) {
    textBox(draw, corner, {"rendering the first image..."}, kBoxColor, width);
    return;
  }
  struct Box {
    std::vector<std::string> lines;
    ImU32 color;
  };
  std::vector<Box> boxes;  // top to bottom
  if (info.side) boxes.push_back({{std::string(info.side) + " pane"}, kBoxColor});
  if (!frame->error.empty()) {
    boxes.push_back({{frame->integrator + " cannot render:", frame->error}, kErrorBox});
  } else {
    boxes.push_back({counters(*frame, info.side != nullptr), kBoxColor});
    if (!info.gradeLines.empty())
      boxes.push_back({info.gradeLines, info.gradePassed ? kGradePass : kErrorBox});
  }

  // Unfinished stage code: impossible to miss, with the file and line to open.
  std::vector<std::string> todos;
  for (const TodoRecord& todo : frame->todos) {
    if (todos.size() == 4) {
      todos.push_back("... and " + std::to_string(frame->todos.size() - 4) +
                      " more (see the panel)");
      break;
    }
    todos.push_back("TODO not done: " + todo.file + ":" + std::to_string(todo.line) + "  " +
                    todo.task);
  }
  const float legendRoom = info.mode == DisplayMode::Color ? 0.0f : 60.0f;
  float bottom = pane.max.y - margin - legendRoom;
  bottom -= textBox(draw, ImVec2(corner.x, bottom), todos, kTodoBox, width, true) + 4;
  if (info.side) {
    // Split panes are narrow: at the top their boxes would cover the ceiling and its light (the
    // demos' Cornell box), so they stack up from the bottom.
    for (auto box = boxes.rbegin(); box != boxes.rend(); ++box)
      bottom -= textBox(draw, ImVec2(corner.x, bottom), box->lines, box->color, width, true) + 4;
  } else {
    float y = corner.y;
    for (const Box& box : boxes)
      y += textBox(draw, ImVec2(corner.x, y), box.lines, box.color, width) + 4;
  }
  if (info.mode != DisplayMode::Color) legend(draw, pane, info);
}

}  // namespace

ImageLayout layoutPanes(const ViewerState& state, float panelWidth) {
  const ImGuiIO& io = ImGui::GetIO();
  ImageLayout layout;
  layout.count = state.split ? 2 : 1;
  const float gap = state.split ? 4.0f : 0.0f;
  const float left = std::min(panelWidth, io.DisplaySize.x - 16.0f);
  const float paneWidth = std::max(8.0f, (io.DisplaySize.x - left - gap) / layout.count);
  for (int i = 0; i < layout.count; ++i) {
    const float x = left + i * (paneWidth + gap);
    layout.panes[i] = {ImVec2(x, 0.0f), ImVec2(x + paneWidth, io.DisplaySize.y)};
  }
  if (state.fixedWidth > 0 && state.fixedHeight > 0) {
    layout.renderWidth = state.fixedWidth;
    layout.renderHeight = state.fixedHeight;
  } else {
    const float divisor = static_cast<float>(std::max(state.resolutionDivisor, 1));
    layout.renderWidth =
        std::max(8, static_cast<int>(paneWidth * io.DisplayFramebufferScale.x / divisor));
    layout.renderHeight =
        std::max(8, static_cast<int>(io.DisplaySize.y * io.DisplayFramebufferScale.y / divisor));
  }
  return layout;
}

void drawPane(const Pane& pane, const GlTexture& texture, const PaneInfo& info) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  draw->PushClipRect(pane.min, pane.max);  // a pane's text never spills into the other pane
  drawPaneContent(draw, pane, texture, info);
  draw->PopClipRect();
}

bool CameraMouse::update(const ImageLayout& layout, OrbitCamera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  bool overImage = false;
  for (int i = 0; i < layout.count; ++i)
    if (layout.panes[i].contains(io.MousePos)) {
      overImage = !io.WantCaptureMouse;
      paneHeight_ = layout.panes[i].height();
    }
  for (int button = 0; button < 3; ++button) {
    if (ImGui::IsMouseClicked(button) && overImage) dragging_[button] = true;
    if (!ImGui::IsMouseDown(button)) dragging_[button] = false;
  }
  bool moved = false;
  const ImVec2 d = io.MouseDelta;
  if (d.x != 0.0f || d.y != 0.0f) {
    if (dragging_[0]) {
      camera.orbit(d.x, d.y);
      moved = true;
    } else if (dragging_[1] || dragging_[2]) {
      camera.pan(d.x, d.y, paneHeight_);
      moved = true;
    }
  }
  if (overImage && io.MouseWheel != 0.0f) {
    camera.zoom(io.MouseWheel);
    moved = true;
  }
  return moved;
}

}  // namespace pathway
