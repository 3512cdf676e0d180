// Options: every value a user can set — a render setting (engine/render_settings.h), a chart's
// (chart/chart_spec.h) or a stage's parameter (framework/stages/) — is declared once as an
// OptionSpec of one kind (integer, real, toggle, choice) with its default, range and help. The CLI
// options, the viewer's widgets, the metadata and the docs are made from the declarations;
// values outside them are refused, never clamped.
#pragma once

#include <map>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace pathway {

enum class OptionKind {
  Integer,  // a whole number in [minValue, maxValue]
  Real,     // a real number in [minValue, maxValue]
  Toggle,   // on or off (written on/off, also accepted as 1/0, true/false)
  Choice,   // one of `options`, by name; stored as the option's index
};

// "integer", "real", "toggle", "choice": as the stages' parameter tables write the kinds.
const char* optionKindName(OptionKind kind);

// What a stage's parameter is to the framework beyond its value: the viewer's Up / Down keys step
// the recursion depth; the grader's difference patterns (grade/difference_patterns.cpp) vary the
// AO reach and the depth, and turn next-event estimation on.
enum class OptionRole { None, RecursionDepth, AoReach, NextEventEstimation };

struct OptionSpec {
  std::string name;  // lower-case, dash-separated: "spp" (--spp), "ao-distance" (-p ao-distance=)
  OptionKind kind = OptionKind::Real;
  double defaultValue = 0.0;
  double minValue = 0.0;
  double maxValue = 0.0;
  std::vector<std::string> options;  // Choice only
  std::string help;
  // Whether another value changes the image the integrator converges to (a ray length, a depth),
  // or only its noise and cost (a sample count, NEE, how lights are picked). References are
  // shared only across values of parameters that do not (charts, the viewer's error plot).
  bool changesExpectedImage = true;
  OptionRole role = OptionRole::None;

  // (The bounds are doubles so that a range can reach 2^64, the seed's.)
  static OptionSpec integer(std::string name, long long defaultValue, double minValue,
                            double maxValue, std::string help);
  static OptionSpec real(std::string name, double defaultValue, double minValue, double maxValue,
                         std::string help);
  static OptionSpec toggle(std::string name, bool defaultValue, std::string help);
  static OptionSpec choice(std::string name, const std::string& defaultOption,
                           std::vector<std::string> options, std::string help);

  // This declaration, marked as one that changes only noise and cost.
  OptionSpec keepingTheExpectedImage() const;
  // This declaration, marked as playing `role` in its stage.
  OptionSpec withRole(OptionRole role) const;
  // This declaration with another default and help, for a command that uses the same setting
  // differently (the viewer refines towards a far larger spp than a render takes).
  OptionSpec withDefault(double value, std::string help) const;

  template <typename T>
  T defaultAs() const {
    if constexpr (std::is_enum_v<T>)
      return static_cast<T>(static_cast<long long>(defaultValue));  // a choice's index
    else
      return static_cast<T>(defaultValue);
  }

  bool isWholeNumber() const { return kind != OptionKind::Real; }
  // True when `value` is one this parameter can take (in range; whole where it must be).
  bool accepts(double value) const;
  // Throws PathwayError "<name> must be in <range>, got <value>" unless it accepts `value`.
  void require(double value) const;
  // The value as a user writes it: "4", "0.25", "on", "power".
  std::string format(double value) const;
  // "[1, 1024]", "on or off", "area or power".
  std::string describeRange() const;
};

// The option of `options` that plays `role`, or nullptr.
const OptionSpec* optionWithRole(const std::vector<OptionSpec>& options, OptionRole role);

// The values of one integrator's parameters, every declared one present.
class ParamValues {
 public:
  ParamValues() = default;
  // Every parameter at its default.
  explicit ParamValues(std::vector<OptionSpec> specs);

  // Sets a declared parameter; throws PathwayError naming `owner`, the parameter and its range
  // when the name is unknown or the value is not one it accepts.
  void set(const std::string& owner, const std::string& name, double value);
  // The same from text as a user writes it ("4", "on", "power").
  void setText(const std::string& owner, const std::string& name, const std::string& text);

  // Throws if the name was never declared. Stages read their typed struct instead
  // (render/stage_definition.h).
  double number(const std::string& name) const;

  const std::vector<OptionSpec>& specs() const { return specs_; }
  // "name=value name=value", in declaration order, each as setText() reads it back.
  std::string describe() const;
  bool operator==(const ParamValues& o) const { return values_ == o.values_; }

 private:
  const OptionSpec& spec(const std::string& owner, const std::string& name) const;

  std::vector<OptionSpec> specs_;
  std::map<std::string, double> values_;
};

// The first parameter that `a` and `b` both declare, that changes the expected image, and that
// they set to different values, as "name=value (not other)"; empty when there is none.
std::string expectedImageDifference(const ParamValues& a, const ParamValues& b);

// The defaults of `specs` with `given` (name -> text) applied; throws PathwayError as set() does.
ParamValues resolveParams(const std::string& owner, const std::vector<OptionSpec>& specs,
                          const std::map<std::string, std::string>& given);

// "name=value" -> (name, value); throws PathwayError on text without '='.
std::pair<std::string, std::string> splitParamAssignment(const std::string& text);
// "name=value name=value", as describe() writes it and a render's metadata keeps it, -> name ->
// text; throws PathwayError on a word without '='.
std::map<std::string, std::string> parseParamList(const std::string& described);

}  // namespace pathway
