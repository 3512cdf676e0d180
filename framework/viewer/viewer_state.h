// What the panel edits, and how it turns into a render job. Nothing here knows about GL or ImGui.
//
// Integrator parameters are remembered per pane and per stage, so "yours" and "reference" of one
// stage share their settings (a fair toggle), and each pane of the split view keeps its own (e.g.
// stage 5 with NEE on the left and off on the right).
#pragma once

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "engine/render_settings.h"
#include "film/pixel_filter.h"
#include "render/integrator_registry.h"
#include "sampling/sampler.h"
#include "scene/gltf_loader.h"
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
  std::string lastReference[2];  // the reference each pane showed last, for T to return to
  // (stage, name) -> value, every value one the parameter accepts (the widgets and the command
  // line refuse others, nothing clamps).
  std::map<std::pair<int, std::string>, double> params[2];

  RenderSettings settings = progressiveSettings();  // width and height: set per job
  int resolutionDivisor = 1;            // render at 1/1, 1/2 or 1/4 of the pane's pixels
  int fixedWidth = 0, fixedHeight = 0;  // from --width/--height; 0: follow the pane

  float exposure = 0.0f;  // stops
  DisplayMode display = DisplayMode::Color;
  float scaleTop = 0.0f;  // a fixed top for the false-colour displays (kScaleTop); 0: their own

  bool split = false;
  Balance balance = Balance::EqualTime;
  // The right pane's own sampler (e.g. Sobol' 4D points against the left pane's independent
  // numbers) and pixel filter (e.g. box against Mitchell); none: both panes use settings'.
  std::optional<SamplerType> splitSampler;
  std::optional<FilterType> splitFilter;
  float budgetSeconds = 0.0f;   // equal time: per pane; 0: up to the spp target
  float budgetMegaRays = 0.0f;  // equal rays: per pane, in millions; 0: up to the spp target

  uint32_t referenceSpp =
      setting::kReferenceSamplesPerPixel.defaultAs<uint32_t>();  // Make reference

  // A window: render beside its UI thread (render_priority.h), on renderThreadsBesideUi threads.
  // Offscreen runs (screenshots, tests) have nobody waiting on their frames: every core.
  bool renderBelowUi = false;
  bool cacheReferences = false;  // references made are kept on disk and found there (demos)

  bool paused = false;
  bool showHelp = false;
  // How scenes load: --strict and --light-scale, the light size widget editing the latter.
  SceneLoadOptions sceneOptions;
};

// The pane's value of a parameter: the one set for its stage, else the declared default.
double paramValue(const ViewerState& state, int lane, const IntegratorInfo& info,
                  const OptionSpec& spec);
// Throws PathwayError (naming the parameter and its range) for a value it does not accept.
void setParamValue(ViewerState& state, int lane, const IntegratorInfo& info, const OptionSpec& spec,
                   double value);

// Steps the recursion depth (OptionRole::RecursionDepth) of every pane shown by `steps`, kept
// within [max(0, lowest), highest]; panes whose integrator does not recurse are left alone.
void stepRecursionDepth(ViewerState& state, int steps);
// Multiplies the lights' size (setting::kLightScale) by `factor`, kept within its range. Returns
// true when it changed (the scene must then load again).
bool scaleLightSize(ViewerState& state, float factor);

// Chooses an integrator for a pane; the left pane's choice also brings its stage's usual sampler.
void selectIntegrator(ViewerState& state, int lane, const std::string& name);
// Yours <-> reference of the pane's stage, when the other one is built in (else returns false).
// The reference is the one the other pane shows (so the two labels match), else the one this pane
// left, else the fastest (stageN@fast where it exists).
bool toggleVariant(ViewerState& state, int lane);
// Stage `stage` in the pane's current variant (or the other one when only that exists); a reference
// is chosen as toggleVariant chooses it.
bool selectStage(ViewerState& state, int lane, int stage);

// Render threads beside a window's UI thread on `cores` cores: one fewer than the cores, so the UI
// keeps a core for its frames (measured on 2 cores: docs/benchmarks.md, "The figures in brief");
// 0 (all) on one core.
int renderThreadsBesideUi(unsigned cores);

// The job for panes of `width` x `height` render pixels.
WorkerJob makeJob(const ViewerState& state, std::shared_ptr<const LoadedScene> scene,
                  const CameraPose& camera, int width, int height);

}  // namespace pathway
