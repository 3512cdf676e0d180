#include "render/stage_kit.h"

#include <optional>

#include "core/error.h"
#include "render/integrator_registry.h"
#include "render/registration_gate.h"

namespace pathway {
namespace {

int slot(Variant variant) {
  return variant == Variant::Student ? 0 : 1;
}

// Filled before main() runs by the stage files' registrations; empty where a stage is missing.
struct Provided {
  std::optional<Stage1Functions> stage1;
  std::optional<Stage2Functions> stage2;
  std::optional<Stage5Functions> stage5;
};

Provided& provided(Variant variant) {
  static Provided table[2];
  return table[slot(variant)];
}

[[noreturn]] void missing(int stage, Variant variant) {
  if (variant == Variant::Reference) throw PathwayError(referenceStageMissing(stage));
  throw PathwayError("the student stage " + std::to_string(stage) +
                     " is not built into this program");
}

}  // namespace

std::string earlierStagesName(EarlierStages source) {
  return source == EarlierStages::Own ? "own" : "reference";
}

EarlierStages parseEarlierStages(const std::string& name) {
  if (name == "own") return EarlierStages::Own;
  if (name == "reference") return EarlierStages::Reference;
  throw PathwayError("unknown source of earlier stages '" + name + "' (choose own or reference)");
}

StageKit::StageKit(int stage, Variant variant, EarlierStages earlier) {
  const Variant before = earlier == EarlierStages::Own ? variant : Variant::Reference;
  for (int earlierStage = 1; earlierStage <= 2; ++earlierStage)
    variants_[earlierStage - 1] = earlierStage < stage ? before : variant;
}

const Stage1Functions& StageKit::stage1() const {
  const auto& functions = provided(variants_[0]).stage1;
  if (!functions) missing(1, variants_[0]);
  return *functions;
}

const Stage2Functions& StageKit::stage2() const {
  const auto& functions = provided(variants_[1]).stage2;
  if (!functions) missing(2, variants_[1]);
  return *functions;
}

const Stage5Functions& stage5Functions(Variant variant) {
  const auto& functions = provided(variant).stage5;
  if (!functions)
    throw PathwayError(std::string("stage 5 (") + variantName(variant) +
                       ") hands no light sampling on: is it built into this program, and does its "
                       "file end with registerStage<PathTracer>(stage5(), "
                       "Stage5Functions{sampleLight})?");
  return *functions;
}

void provideStage1(Variant variant, const Stage1Functions& functions) {
  if (admitRegistration(1, variant, "stage 1's functions")) provided(variant).stage1 = functions;
}

void provideStage2(Variant variant, const Stage2Functions& functions) {
  if (admitRegistration(2, variant, "stage 2's functions")) provided(variant).stage2 = functions;
}

void provideStage5(Variant variant, const Stage5Functions& functions) {
  if (admitRegistration(5, variant, "stage 5's functions")) provided(variant).stage5 = functions;
}

}  // namespace pathway
