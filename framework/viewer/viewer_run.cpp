// From the command line to a running viewer: the options become the panel's first state, the scene
// is loaded, and a window (or, with --headless, an OSMesa context) opens; with --frames the viewer
// draws that many frames and writes a screenshot.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "core/error.h"
#include "engine/render_choices.h"
#include "render/integrator_registry.h"
#include "viewer/viewer_app.h"

namespace pathway {
namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

int runViewer(const ViewerOptions& options) {
  if (options.benchmark) return runViewerBenchmark(options);
  ViewerState state = initialState(options);  // bad names fail before any window opens
  auto scene = LoadedScene::load(options.choices.scene, options.choices.sceneOptions());
  completeRenderSize(state, scene->scene);
  std::optional<ReferenceImage> reference;
  if (!options.reference.empty()) {
    // A file holds no camera: it is taken to show the scene's own, where the viewer starts.
    const ReferenceView view{scene->scene.sourcePath,
                             scene->contentHash,
                             OrbitCamera(scene->scene).pose(),
                             state.settings.filter,
                             state.settings.filterRadiusPixels(),
                             {}};
    reference = loadReference(options.reference, view);  // a bad file fails before any window
  }
  state.renderBelowUi = !options.headless;  // someone is using the window while it renders
  std::unique_ptr<Platform> platform =
      options.headless ? createOsmesaPlatform(options.windowWidth, options.windowHeight)
                       : createGlfwPlatform(options.windowWidth, options.windowHeight, "Pathway");
  Viewer viewer(std::move(platform), std::move(state), std::move(scene));
  if (reference) viewer.setReference(std::move(*reference));

  const std::string screenshot = !options.screenshot.empty() ? options.screenshot
                                 : (options.headless && !options.prepareReference)
                                     ? "pathway_view_screenshot.png"
                                     : "";
  const int frames = options.frames > 0 ? options.frames : (options.headless ? 30 : 0);
  // A screenshot should show a render: after the frames asked for, keep drawing (for at most
  // this long) until every pane has its first image.
  constexpr double kFirstImageTimeout = 30.0;
  double deadline = 0.0;
  bool gradeAsked = false, referenceAsked = false;
  for (int drawn = 0; !viewer.shouldClose(); ++drawn) {
    if (options.grade && !gradeAsked && viewer.panesCurrent()) {
      viewer.toggleGrade();
      gradeAsked = true;
    }
    if (options.makeReference && !referenceAsked && viewer.panesCurrent()) {
      viewer.toggleMakeReference();
      referenceAsked = true;
    }
    // The frames asked for count once the reference is in (the panes then start over).
    const bool waitingForReference =
        options.makeReference && (!referenceAsked || viewer.makingReference());
    if (waitingForReference) drawn = 0;
    const bool enough = frames > 0 && drawn + 1 >= frames && !waitingForReference;
    if (enough && deadline == 0.0) deadline = now() + kFirstImageTimeout;
    const bool gradeShown = !options.grade || (gradeAsked && !viewer.grading());
    const bool last = enough && ((viewer.panesCurrent() && gradeShown) || now() > deadline);
    viewer.frame(last ? screenshot : "");
    if (last) break;
    viewer.waitForChange();
  }
  if (!screenshot.empty() && frames > 0) std::printf("wrote %s\n", screenshot.c_str());
  if (frames > 0 && viewer.hasReference()) {  // what the plot ended at, for scripts and tests
    std::printf("error plot reference: %s\n", viewer.referenceSource().c_str());
    const int lanes = options.splitIntegrator.empty() ? 1 : 2;
    for (int lane = 0; lane < lanes; ++lane) {
      const ErrorHistory& history = viewer.errors(lane);
      const char* pane = lanes == 1 ? "" : lane == 0 ? "left " : "right ";
      if (!history.points().empty()) {
        const ErrorPoint& last = history.points().back();
        std::printf("error plot, %s%s: relMSE %.4g at %u spp, %.3f s (%zu points)\n", pane,
                    history.integrator().c_str(), last.relMse, last.spp, last.seconds,
                    history.points().size());
      } else {
        std::printf("error plot, %s%s: not measured%s%s\n", pane, history.integrator().c_str(),
                    history.message().empty() ? "" : ": ", history.message().c_str());
      }
    }
  }
  return 0;
}

}  // namespace pathway
