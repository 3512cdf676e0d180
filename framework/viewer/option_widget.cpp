#include "viewer/option_widget.h"

#include <imgui.h>

#include <cmath>
#include <limits>

#include "viewer/panel.h"

namespace pathway {

bool optionWidget(const char* label, const OptionSpec& spec, double& value, const char* format) {
  const ImGuiSliderFlags clamp = ImGuiSliderFlags_AlwaysClamp;
  bool changed = false;
  double result = value;
  switch (spec.kind) {
    case OptionKind::Toggle: {
      bool on = value != 0.0;
      changed = ImGui::Checkbox(label, &on);
      result = on ? 1.0 : 0.0;
      break;
    }
    case OptionKind::Choice: {
      const auto chosen = static_cast<size_t>(value);
      if (ImGui::BeginCombo(label, spec.format(value).c_str())) {
        for (size_t i = 0; i < spec.options.size(); ++i) {
          if (ImGui::Selectable(spec.options[i].c_str(), i == chosen)) {
            changed = i != chosen;
            result = static_cast<double>(i);
          }
        }
        ImGui::EndCombo();
      }
      break;
    }
    case OptionKind::Integer: {
      // 64-bit: some limits (e.g. a ray budget) go far beyond int.
      long long v = static_cast<long long>(value);
      const long long lo = static_cast<long long>(spec.minValue);
      // (A range past long long, the seed's, is cut at its end.)
      const long long hi = spec.maxValue < 9.2e18 ? static_cast<long long>(spec.maxValue)
                                                  : std::numeric_limits<long long>::max();
      const char* shown = format ? format : "%lld";
      if (hi - lo <= 64)
        changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &v, &lo, &hi, shown, clamp);
      else if (lo > 0)  // counts over decades (samples, rays per hit, budgets): a log scale
        changed = ImGui::SliderScalar(label, ImGuiDataType_S64, &v, &lo, &hi, shown,
                                      clamp | ImGuiSliderFlags_Logarithmic);
      else
        changed = ImGui::DragScalar(label, ImGuiDataType_S64, &v, 0.2f, &lo, &hi, shown, clamp);
      result = static_cast<double>(v);
      break;
    }
    case OptionKind::Real: {
      double v = value;
      ImGuiSliderFlags flags = clamp;
      // Ranges over decades (distances, strengths) are easier to set on a log scale.
      if (spec.minValue > 0.0 && spec.maxValue / spec.minValue >= 100.0)
        flags |= ImGuiSliderFlags_Logarithmic;
      changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &v, &spec.minValue, &spec.maxValue,
                                    format ? format : "%.4g", flags);
      result = v;
      break;
    }
  }
  const bool typed = spec.kind == OptionKind::Integer || spec.kind == OptionKind::Real;
  tooltip(spec.help + "\n(default " + spec.format(spec.defaultValue) + ", " + spec.describeRange() +
          (typed ? "; Ctrl+click to type a value)" : ")"));
  if (changed) value = result;
  return changed;
}

}  // namespace pathway
