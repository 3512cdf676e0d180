#include "viewer/viewer_state.h"

#include <algorithm>
#include <cmath>

namespace pathway {
namespace {

const IntegratorInfo* find(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return info;
  return nullptr;
}

const IntegratorInfo* findStage(int stage, Variant variant) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->stage == stage && info->variant == variant) return info;
  return nullptr;
}

}  // namespace

double paramValue(const ViewerState& state, int lane, const IntegratorInfo& info,
                  const ParamSpec& spec) {
  const auto it = state.params[lane].find({info.stage, spec.name});
  const double value = it != state.params[lane].end() ? it->second : spec.defaultValue;
  return std::clamp(value, spec.minValue, spec.maxValue);
}

void setParamValue(ViewerState& state, int lane, const IntegratorInfo& info, const ParamSpec& spec,
                   double value) {
  value = std::clamp(value, spec.minValue, spec.maxValue);
  if (spec.isInteger) value = std::round(value);
  state.params[lane][{info.stage, spec.name}] = value;
}

void selectIntegrator(ViewerState& state, int lane, const std::string& name) {
  const IntegratorInfo* info = find(name);
  if (!info) return;
  if (lane == 0 && name != state.integrator[0]) state.sampler = info->defaultSampler;
  state.integrator[lane] = name;
}

bool toggleVariant(ViewerState& state, int lane) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  if (!current) return false;
  const Variant other =
      current->variant == Variant::Student ? Variant::Reference : Variant::Student;
  const IntegratorInfo* info = findStage(current->stage, other);
  if (!info) return false;
  state.integrator[lane] = info->name;
  return true;
}

bool selectStage(ViewerState& state, int lane, int stage) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  const Variant variant = current ? current->variant : Variant::Student;
  const IntegratorInfo* info = findStage(stage, variant);
  if (!info)
    info = findStage(stage, variant == Variant::Student ? Variant::Reference : Variant::Student);
  if (!info) return false;
  selectIntegrator(state, lane, info->name);
  return true;
}

WorkerJob makeJob(const ViewerState& state, std::shared_ptr<const LoadedScene> scene,
                  const CameraPose& camera, int width, int height) {
  WorkerJob job;
  job.scene = std::move(scene);
  job.camera = camera;
  RenderSettings& s = job.settings;
  s.width = std::max(width, 1);
  s.height = std::max(height, 1);
  s.samplesPerPixel = static_cast<uint32_t>(std::max(state.sppTarget, 1));
  s.samplesPerPass = static_cast<uint32_t>(std::clamp(state.samplesPerPass, 1, state.sppTarget));
  s.sampler = state.sampler;
  s.seed = static_cast<uint64_t>(state.seed);
  s.filter = state.filter;
  s.filterRadius = state.filterRadius;
  for (int lane = 0; lane < (state.split ? 2 : 1); ++lane) {
    LaneJob laneJob;
    laneJob.integrator = state.integrator[lane];
    if (const IntegratorInfo* info = find(laneJob.integrator))
      for (const ParamSpec& spec : info->params)
        laneJob.params[spec.name] = paramValue(state, lane, *info, spec);
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
