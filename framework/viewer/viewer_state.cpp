#include "viewer/viewer_state.h"

#include <algorithm>
#include <cmath>

#include "viewer/viewer_options.h"

namespace pathway {
namespace {

const IntegratorInfo* find(const std::string& name) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == name) return info;
  return nullptr;
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

void selectIntegrator(ViewerState& state, int lane, const std::string& name) {
  const IntegratorInfo* info = find(name);
  if (!info) return;
  if (lane == 0 && name != state.integrator[0]) state.settings.sampler = info->defaultSampler;
  state.integrator[lane] = name;
}

bool toggleVariant(ViewerState& state, int lane) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  if (!current) return false;
  const Variant other =
      current->variant == Variant::Student ? Variant::Reference : Variant::Student;
  const IntegratorInfo* info = findStageIntegrator(current->stage, other);
  if (!info) return false;
  // The reference renders with its wavefront version where there is one: the same image, sooner.
  if (other == Variant::Reference)
    info = &findIntegrator(referenceIntegratorName(current->stage, ReferenceTracing::Fastest));
  state.integrator[lane] = info->name;
  return true;
}

bool selectStage(ViewerState& state, int lane, int stage) {
  const IntegratorInfo* current = find(state.integrator[lane]);
  const Variant variant = current ? current->variant : Variant::Student;
  const IntegratorInfo* info =
      variant == Variant::Reference && findStageIntegrator(stage, variant)
          ? &findIntegrator(referenceIntegratorName(stage, ReferenceTracing::Fastest))
          : findStageIntegrator(stage, variant);
  if (!info && variant == Variant::Student && findStageIntegrator(stage, Variant::Reference))
    info = &findIntegrator(referenceIntegratorName(stage, ReferenceTracing::Fastest));
  if (!info) info = findStageIntegrator(stage, Variant::Student);
  if (!info) return false;
  selectIntegrator(state, lane, info->name);
  return true;
}

WorkerJob makeJob(const ViewerState& state, std::shared_ptr<const LoadedScene> scene,
                  const CameraPose& camera, int width, int height) {
  WorkerJob job;
  job.scene = std::move(scene);
  job.camera = camera;
  job.settings = state.settings;
  job.settings.width = std::max(width, 1);
  job.settings.height = std::max(height, 1);
  for (int lane = 0; lane < (state.split ? 2 : 1); ++lane) {
    LaneJob laneJob;
    laneJob.integrator = state.integrator[lane];
    laneJob.earlierStages = state.earlierStages[lane];
    if (const IntegratorInfo* info = find(laneJob.integrator))
      for (const OptionSpec& spec : info->params)
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
