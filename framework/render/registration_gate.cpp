#include "render/registration_gate.h"

#include <cstdio>
#include <cstdlib>
#include <optional>
#include <vector>

namespace pathway {
namespace {

struct Gate {
  bool builtInOpen = true;  // before endBuiltInRegistrations
  // The windows open now, innermost last (a library's initializer may load another library).
  struct Open {
    RegistrationWindow window;
    int stage = 0;  // the stage it registers, once known
    std::string refusal;
  };
  std::vector<Open> windows;
};

Gate& gate() {
  static Gate state;
  return state;
}

std::string variantText(Variant variant) {
  return variant == Variant::Reference ? "the reference" : "the student's";
}

}  // namespace

void openRegistrationWindow(const RegistrationWindow& window) {
  gate().windows.push_back({window, window.stage, ""});
}

std::string closeRegistrationWindow() {
  if (gate().windows.empty()) return "";
  const std::string refusal = gate().windows.back().refusal;
  gate().windows.pop_back();
  return refusal;
}

void endBuiltInRegistrations() {
  gate().builtInOpen = false;
}

bool admitRegistration(int stage, Variant variant, const std::string& what) {
  Gate& state = gate();
  if (state.windows.empty()) {
    if (state.builtInOpen) return true;
    std::fprintf(stderr,
                 "pathway: refused: %s tried to register after its library was loaded (a stage "
                 "registers once, as its file's last line)\n",
                 what.c_str());
    std::fflush(stderr);
    std::_Exit(70);
  }
  Gate::Open& open = state.windows.back();
  if (!open.refusal.empty()) return false;  // after one refusal, nothing more of that library
  const auto refuse = [&](const std::string& why) {
    open.refusal = what + " was refused: " + why;
    return false;
  };
  if (stage != 0 && open.stage != 0 && stage != open.stage) {
    if (open.window.variant == Variant::Reference) return false;  // an earlier stage's code
    return refuse("this library registers stage " + std::to_string(open.stage) +
                  ", and a library registers one stage only");
  }
  if (variant != open.window.variant)
    return refuse("it is loaded as " + variantText(open.window.variant) + " and registered as " +
                  variantText(variant));
  if (stage == 0) return refuse("a stage library registers its stage and nothing else");
  open.stage = stage;
  return true;
}

}  // namespace pathway
