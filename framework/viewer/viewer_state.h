// What the panel edits, and how it turns into a render job. Nothing here knows about GL or ImGui.
//
// Integrator parameters are remembered per pane and per stage, so "yours" and "reference" of one
// stage share their settings (a fair toggle), and each pane of the split view keeps its own (e.g.
// stage 5 with NEE on the left and off on the right).
#pragma once

#include <map>
#include <string>
#include <utility>

#include "film/pixel_filter.h"
#include "render/integrator_registry.h"
#include "render/renderer.h"
#include "sampling/sampler.h"
#include "viewer/display_image.h"
#include "viewer/render_worker.h"

namespace pathway {

struct ViewerState {
  std::string integrator[2] = {"stage1", "stage1"};         // left (or only) pane, right pane
  std::map<std::pair<int, std::string>, double> params[2];  // (stage, name) -> value

  FilterType filter = FilterType::Box;
  float filterRadius = 0.0f;  // 0: the filter's natural radius
  SamplerType sampler = SamplerType::Independent;
  int seed = 0;
  int sppTarget = 4096;
  int samplesPerPass = 1;
  int resolutionDivisor = 1;            // render at 1/1, 1/2 or 1/4 of the pane's pixels
  int fixedWidth = 0, fixedHeight = 0;  // from --width/--height; 0: follow the pane

  float exposure = 0.0f;  // stops
  DisplayMode display = DisplayMode::Color;

  bool split = false;
  Balance balance = Balance::EqualTime;
  float budgetSeconds = 0.0f;   // equal time: per pane; 0: up to the spp target
  float budgetMegaRays = 0.0f;  // equal rays: per pane, in millions; 0: up to the spp target

  bool paused = false;
  bool showHelp = false;
};

double paramValue(const ViewerState& state, int lane, const IntegratorInfo& info,
                  const ParamSpec& spec);
void setParamValue(ViewerState& state, int lane, const IntegratorInfo& info, const ParamSpec& spec,
                   double value);

// Chooses an integrator for a pane; the left pane's choice also brings its stage's usual sampler.
void selectIntegrator(ViewerState& state, int lane, const std::string& name);
// stageN <-> stageN@ref in that pane, when the other one is built in. Returns false otherwise.
bool toggleVariant(ViewerState& state, int lane);
// Stage `stage` in the pane's current variant (or the other one when only that exists).
bool selectStage(ViewerState& state, int lane, int stage);

// The job for panes of `width` x `height` render pixels.
WorkerJob makeJob(const ViewerState& state, std::shared_ptr<const LoadedScene> scene,
                  const CameraPose& camera, int width, int height);

}  // namespace pathway
