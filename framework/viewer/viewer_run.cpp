// From the command line to a running viewer: the options become the panel's first state, the scene
// is loaded, and a window (or, with --headless, an OSMesa context) opens; with --frames the viewer
// draws that many frames and writes a screenshot.
#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <map>

#include "core/error.h"
#include "render/integrator_registry.h"
#include "render/parameters.h"
#include "viewer/viewer_app.h"

namespace pathway {
namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void applyParams(ViewerState& state, int lane, const std::string& integrator,
                 const std::vector<std::string>& assignments) {
  const IntegratorInfo& info = findIntegrator(integrator);
  std::map<std::string, std::string> given;
  for (const std::string& assignment : assignments) given.insert(splitParamAssignment(assignment));
  const ParamValues values = resolveParams(info.name, info.params, given);
  for (const ParamSpec& spec : info.params)
    setParamValue(state, lane, info, spec, values.number(spec.name));
  state.integrator[lane] = info.name;
}

}  // namespace

ViewerState initialState(const ViewerOptions& options) {
  ViewerState state;
  const IntegratorInfo& info = findIntegrator(options.integrator);
  applyParams(state, 0, info.name, options.params);
  state.sampler = options.sampler.empty() ? info.defaultSampler : parseSamplerType(options.sampler);
  state.integrator[1] = state.integrator[0];
  if (!options.splitIntegrator.empty()) {
    applyParams(state, 1, options.splitIntegrator, options.splitParams);
    state.split = true;
  }
  if (options.balance == "time")
    state.balance = Balance::EqualTime;
  else if (options.balance == "rays")
    state.balance = Balance::EqualRays;
  else
    throw PathwayError("unknown balance '" + options.balance + "' (time or rays)");
  state.filter = parseFilterType(options.filter);
  state.filterRadius = options.filterRadius;
  state.seed = static_cast<int>(std::min<uint64_t>(options.seed, INT_MAX));
  state.sppTarget = static_cast<int>(std::min<uint32_t>(options.spp, 1u << 20));
  state.samplesPerPass = static_cast<int>(std::min(options.samplesPerPass, options.spp));
  state.exposure = options.exposure;
  if (options.display == "color" || options.display == "colour")
    state.display = DisplayMode::Color;
  else if (options.display == "variance")
    state.display = DisplayMode::Variance;
  else if (options.display == "rays")
    state.display = DisplayMode::RayHeatmap;
  else
    throw PathwayError("unknown display '" + options.display + "' (color, variance or rays)");
  state.showHelp = options.showHelp;
  state.fixedWidth = options.width;
  state.fixedHeight = options.height;
  return state;
}

int runViewer(const ViewerOptions& options) {
  if (options.benchmark) return runViewerBenchmark(options);
  ViewerState state = initialState(options);  // bad names fail before any window opens
  auto scene = LoadedScene::load(options.scene);
  if ((state.fixedWidth > 0) != (state.fixedHeight > 0)) {
    // One side given: the other from the scene camera's aspect ratio, as `pathway render` does.
    const float aspect = scene->scene.camera && scene->scene.camera->aspectRatio
                             ? *scene->scene.camera->aspectRatio
                             : 16.0f / 9.0f;
    if (state.fixedHeight == 0)
      state.fixedHeight = std::max(1, static_cast<int>(std::lround(state.fixedWidth / aspect)));
    else
      state.fixedWidth = std::max(1, static_cast<int>(std::lround(state.fixedHeight * aspect)));
  }
  std::unique_ptr<Platform> platform =
      options.headless ? createOsmesaPlatform(options.windowWidth, options.windowHeight)
                       : createGlfwPlatform(options.windowWidth, options.windowHeight, "Pathway");
  Viewer viewer(std::move(platform), std::move(state), std::move(scene));

  const std::string screenshot = !options.screenshot.empty()
                                     ? options.screenshot
                                     : (options.headless ? "pathway_view_screenshot.png" : "");
  const int frames = options.frames > 0 ? options.frames : (options.headless ? 30 : 0);
  // A screenshot should show a render: after the frames asked for, keep drawing (for at most
  // this long) until every pane has its first image.
  constexpr double kFirstImageTimeout = 30.0;
  double deadline = 0.0;
  for (int drawn = 0; !viewer.shouldClose(); ++drawn) {
    const bool enough = frames > 0 && drawn + 1 >= frames;
    if (enough && deadline == 0.0) deadline = now() + kFirstImageTimeout;
    const bool last = enough && (viewer.panesCurrent() || now() > deadline);
    viewer.frame(last ? screenshot : "");
    if (last) break;
    viewer.waitForChange();
  }
  if (!screenshot.empty() && frames > 0) std::printf("wrote %s\n", screenshot.c_str());
  return 0;
}

}  // namespace pathway
