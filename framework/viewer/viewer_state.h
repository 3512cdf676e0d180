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
#include "render/render_settings.h"
#include "sampling/sampler.h"
#include "viewer/display_image.h"
#include "viewer/render_worker.h"

namespace pathway {

// The viewer's render settings before the panes give them a size: it refines progressively, so it
// aims at more samples per pixel than `pathway render`.
RenderSettings progressiveSettings();

struct ViewerState {
  std::string integrator[2] = {setting::kIntegrator,
                               setting::kIntegrator};  // left (or only) pane, right pane
  EarlierStages earlierStages[2] = {EarlierStages::Own, EarlierStages::Own};
  // (stage, name) -> value, every value one the parameter accepts (the widgets and the command
  // line refuse others, nothing clamps).
  std::map<std::pair<int, std::string>, double> params[2];

  RenderSettings settings = progressiveSettings();  // width and height: set per job
  int resolutionDivisor = 1;            // render at 1/1, 1/2 or 1/4 of the pane's pixels
  int fixedWidth = 0, fixedHeight = 0;  // from --width/--height; 0: follow the pane

  float exposure = 0.0f;  // stops
  DisplayMode display = DisplayMode::Color;

  bool split = false;
  Balance balance = Balance::EqualTime;
  float budgetSeconds = 0.0f;   // equal time: per pane; 0: up to the spp target
  float budgetMegaRays = 0.0f;  // equal rays: per pane, in millions; 0: up to the spp target

  uint32_t referenceSpp =
      setting::kReferenceSamplesPerPixel.defaultAs<uint32_t>();  // Make reference

  bool paused = false;
  bool showHelp = false;
  bool strictScene = false;  // scenes opened from the panel: refuse required lamps (--strict)
};

// The pane's value of a parameter: the one set for its stage, else the declared default.
double paramValue(const ViewerState& state, int lane, const IntegratorInfo& info,
                  const OptionSpec& spec);
// Throws PathwayError (naming the parameter and its range) for a value it does not accept.
void setParamValue(ViewerState& state, int lane, const IntegratorInfo& info, const OptionSpec& spec,
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
