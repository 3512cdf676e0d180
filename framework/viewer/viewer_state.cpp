#include "viewer/viewer_state.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "viewer/viewer_options.h"

namespace pathway {
namespace {

const IntegratorInfo* find(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return info;
  return nullptr;
}

// A pane leaving a reference remembers which one, to come back to it (T).
void rememberReference(ViewerState& state, int lane) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  if (current && current->variant == Variant::Reference) state.lastReference[lane] = current->name;
}

// The reference a pane switches to for stage `stage`: the one the other pane of the split view
// shows, else the one this pane showed before, else the fastest, so both panes' labels match.
const IntegratorInfo* referenceFor(const ViewerState& state, int lane, int stage) {
  auto ofStage = [stage](const std::string& name) {
    const IntegratorInfo* info = find(name);
    return info && info->stage == stage && info->variant == Variant::Reference ? info : nullptr;
  };
  if (state.split)
    if (const IntegratorInfo* other = ofStage(state.integrator[1 - lane])) return other;
  if (const IntegratorInfo* before = ofStage(state.lastReference[lane])) return before;
  if (!findStageIntegrator(stage, Variant::Reference)) return nullptr;
  // A pane that showed a reference one ray at a time (stageN@ref) keeps doing so.
  for (const std::string& shown : {state.integrator[lane], state.lastReference[lane]}) {
    const IntegratorInfo* info = find(shown);
    if (info && info->variant == Variant::Reference && !info->wavefront)
      return findStageIntegrator(stage, Variant::Reference);
  }
  // The reference renders with its wavefront version where there is one: the same image, sooner.
  return &findIntegrator(referenceIntegratorName(stage, ReferenceTracing::Fastest));
}

}  // namespace

RenderSettings progressiveSettings() {
  RenderSettings settings;
  settings.samplesPerPixel = kViewerSamplesPerPixel.defaultAs<uint32_t>();
  return settings;
}

double paramValue(const ViewerState& state, int lane, const IntegratorInfo& info,
                  const OptionSpec& spec) {
  const auto it = state.params[lane].find({info.stage, spec.name});
  return it != state.params[lane].end() ? it->second : spec.defaultValue;
}

void setParamValue(ViewerState& state, int lane, const IntegratorInfo& info, const OptionSpec& spec,
                   double value) {
  ParamValues(info.params).set(info.name, spec.name, value);  // refuses what it does not accept
  state.params[lane][{info.stage, spec.name}] = value;
}

void stepRecursionDepth(ViewerState& state, int steps) {
  for (int lane = 0; lane < (state.split ? 2 : 1); ++lane) {
    const IntegratorInfo* info = find(state.integrator[lane]);
    if (!info) continue;
    for (const OptionSpec& spec : info->params) {
      if (spec.role != OptionRole::RecursionDepth) continue;
      // -1 (no limit) is not a step on the way from 0 up.
      const double value = std::clamp(paramValue(state, lane, *info, spec) + steps,
                                      std::max(0.0, spec.minValue), spec.maxValue);
      setParamValue(state, lane, *info, spec, value);
    }
  }
}

bool scaleLightSize(ViewerState& state, float factor) {
  const OptionSpec& spec = setting::kLightScale;
  float& scale = state.sceneOptions.lightScale;
  const float scaled =
      std::clamp(static_cast<double>(scale) * factor, spec.minValue, spec.maxValue);
  if (scaled == scale) return false;
  scale = scaled;
  return true;
}

void selectIntegrator(ViewerState& state, int lane, const std::string& name) {
  const IntegratorInfo* info = find(name);
  if (!info) return;
  if (lane == 0 && name != state.integrator[0]) state.settings.sampler = info->defaultSampler;
  rememberReference(state, lane);
  state.integrator[lane] = name;
}

bool toggleVariant(ViewerState& state, int lane) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  if (!current) return false;
  const IntegratorInfo* info = current->variant == Variant::Student
                                   ? referenceFor(state, lane, current->stage)
                                   : findStageIntegrator(current->stage, Variant::Student);
  if (!info) return false;
  rememberReference(state, lane);
  state.integrator[lane] = info->name;
  return true;
}

bool selectStage(ViewerState& state, int lane, int stage) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  const Variant variant = current ? current->variant : Variant::Student;
  const IntegratorInfo* info = variant == Variant::Reference
                                   ? referenceFor(state, lane, stage)
                                   : findStageIntegrator(stage, Variant::Student);
  if (!info && variant == Variant::Student) info = referenceFor(state, lane, stage);
  if (!info) info = findStageIntegrator(stage, Variant::Student);
  if (!info) return false;
  selectIntegrator(state, lane, info->name);
  return true;
}

int renderThreadsBesideUi(unsigned cores) {
  return cores > 1 ? static_cast<int>(cores) - 1 : 0;
}

WorkerJob makeJob(const ViewerState& state, std::shared_ptr<const LoadedScene> scene,
                  const CameraPose& camera, int width, int height) {
  WorkerJob job;
  job.scene = std::move(scene);
  job.camera = camera;
  job.settings = state.settings;
  job.settings.width = std::max(width, 1);
  job.settings.height = std::max(height, 1);
  if (state.renderBelowUi)
    job.settings.threads = renderThreadsBesideUi(std::thread::hardware_concurrency());
  for (int lane = 0; lane < (state.split ? 2 : 1); ++lane) {
    LaneJob laneJob;
    laneJob.integrator = state.integrator[lane];
    laneJob.earlierStages = state.earlierStages[lane];
    if (const IntegratorInfo* info = find(laneJob.integrator))
      for (const OptionSpec& spec : info->params)
        laneJob.params[spec.name] = paramValue(state, lane, *info, spec);
    if (lane == 1) {
      laneJob.sampler = state.splitSampler;
      laneJob.filter = state.splitFilter;
    }
    job.lanes.push_back(std::move(laneJob));
  }
  if (state.split) {
    job.balance = state.balance;
    job.budget =
        state.balance == Balance::EqualTime ? state.budgetSeconds : state.budgetMegaRays * 1e6;
  }
  return job;
}

}  // namespace pathway
