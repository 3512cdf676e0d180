// Integrators are found by name. Each stage file registers its integrator once (through
// registerStage in render/stage_api.h); the student's version is "stageN", the reference (from
// solutions/) "stageN@ref". Where the reference also has a wavefront version
// (render/wavefront.h), it is "stageN@fast": the same estimator, many paths at a time.
// Benchmarks may register integrators of their own.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "core/variant.h"
#include "render/integrator.h"
#include "render/parameters.h"
#include "render/stage_definition.h"
#include "render/stage_kit.h"

namespace pathway {

// What an integrator is built from.
struct IntegratorSetup {
  const ParamValues& params;  // every declared parameter, checked against its declaration
  const StageKit& kit;        // the earlier stages' functions
  const Scene& scene;
};

using IntegratorFactory = std::function<std::unique_ptr<Integrator>(const IntegratorSetup&)>;

struct IntegratorInfo {
  std::string name;  // "stage2", "stage2@ref" or "stage5@fast"
  int stage = 0;     // 1..5, the course stage it belongs to; 0 for others
  Variant variant = Variant::Student;
  std::string summary;  // one line for --list
  std::vector<OptionSpec> params;
  // The sampler this integrator is meant to be seen with, when the user does not choose one.
  SamplerType defaultSampler = SamplerType::Independent;
  // Builds the integrator; may throw PathwayError for parameter combinations it refuses (before
  // any rendering starts).
  IntegratorFactory create;
  bool wavefront = false;  // a reference's wavefront version ("stageN@fast")

  // The kit this integrator renders with when its earlier stages come from `earlier`.
  StageKit kit(EarlierStages earlier = EarlierStages::Own) const {
    return StageKit(stage, variant, earlier);
  }
};

// Registers at static-initialisation time; returns true so it can initialise a static bool.
bool registerIntegrator(IntegratorInfo info);
// Registers a stage of `variant` under its declared name, summary and parameters
// (render/stage_definition.h), running the stage's own checks before `factory`.
bool registerStageIntegrator(const StageInfo& stage, Variant variant, IntegratorFactory factory);
// Registers the wavefront version of a reference stage as "stageN@fast", with the stage's
// declared summary and parameters.
bool registerWavefrontStageIntegrator(const StageInfo& stage, IntegratorFactory factory);

// Why stage `stage` of `variant` is missing, as the code that loads stage libraries found it
// (stage_loading/): the registry knows what registered, not where stages come from.
void noteMissingStage(int stage, Variant variant, std::string why);
// What was noted for stage `stage` of `variant`, or "".
std::string missingStageReason(int stage, Variant variant);
// "the reference stage 3 is not available (WHY)": for messages where one is needed but missing.
std::string referenceStageMissing(int stage);

// Every registration so far, in order. A name appears twice when a stage library
// (stage_loading/stage_library.h) replaced a built-in stage.
const std::vector<std::string>& registrationLog();

// Throws PathwayError listing the known names when `name` is unknown. (A view, not a string
// reference: the result outlives a temporary name, and GCC 14 would warn that it might not.)
const IntegratorInfo& findIntegrator(std::string_view name);
// Stage `stage` of `variant`, or nullptr when it is not built in.
const IntegratorInfo* findStageIntegrator(int stage, Variant variant);
// All integrators, sorted by stage, student before reference.
std::vector<const IntegratorInfo*> allIntegrators();

// The name stage `stage` registers under in `variant`: "stage2" or "stage2@ref".
std::string stageIntegratorName(int stage, Variant variant);

// How renders that are not student code (references, calibration, chart references, cluster
// renders) trace the reference: its wavefront version where the stage has one, or always one
// ray at a time (their --single-ray flag).
enum class ReferenceTracing { Fastest, SingleRay };
// The integrator such a render uses for stage `stage`: "stageN@fast" or "stageN@ref".
std::string referenceIntegratorName(int stage, ReferenceTracing tracing);
// The same for an integrator name: "stageN@ref" becomes "stageN@fast" when that exists and
// `tracing` is Fastest; any other name is returned as it is.
std::string referenceIntegratorFor(const std::string& name, ReferenceTracing tracing);

}  // namespace pathway
