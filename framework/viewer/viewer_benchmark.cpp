// `pathway view --benchmark`: how fast the progressive display is, measured headless (OSMesa) on
// the real viewer, and the render worker alone for comparison. Prints one row per integrator.
// Then how many frames the UI draws while the panes render, as when someone drags a slider: in a
// window when there is a display (e.g. under xvfb-run), rendering on every core and on one fewer.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <thread>

#include "render/integrator_registry.h"
#include "viewer/viewer_app.h"
#include "viewer/viewer_demos.h"

namespace pathway {
namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Figures {
  double firstImage = 0.0;  // submit -> first developed image (worker)
  double firstShown = 0.0;  // viewer start -> first frame showing an image (UI)
  double imagesPerSecond = 0.0;
  double passesPerSecond = 0.0;
  double uiFramesPerSecond = 0.0;
  double megaRaysPerSecond = 0.0;
  uint32_t spp = 0;
};

Figures measureViewer(const ViewerOptions& options, std::shared_ptr<const LoadedScene> scene) {
  Figures f;
  const double start = now();
  ViewerState state = initialState(options);
  const int windowWidth = static_cast<int>(kPanelWidth) + options.width;
  const int windowHeight = std::max(options.height, 600);
  Viewer viewer(createOsmesaPlatform(windowWidth, windowHeight), std::move(state), scene);
  int frames = 0;
  double firstShownAt = 0.0;
  uint64_t passesAtFirst = 0, imagesAtFirst = 0;
  for (;;) {
    viewer.frame();
    ++frames;
    if (firstShownAt == 0.0 && viewer.panesCurrent() && viewer.imagesShown() > 0) {
      firstShownAt = now();
      f.firstShown = firstShownAt - start;
      passesAtFirst = viewer.worker().passesDone();
      imagesAtFirst = viewer.imagesShown();
      frames = 0;
    }
    if (firstShownAt > 0.0 && now() - firstShownAt >= options.benchmarkSeconds) break;
    if (now() - start > 60.0) break;
    viewer.waitForChange(true);  // draw when an image arrives, as the window does
  }
  const double seconds = now() - firstShownAt;
  f.imagesPerSecond = (viewer.imagesShown() - imagesAtFirst) / seconds;
  f.passesPerSecond = (viewer.worker().passesDone() - passesAtFirst) / seconds;
  f.uiFramesPerSecond = frames / seconds;
  if (const auto frame = viewer.worker().frame(0)) {
    f.firstImage = frame->firstImageSeconds;
    f.spp = frame->stats.samplesPerPixel;
    f.megaRaysPerSecond = frame->stats.counters.totalRays() / frame->stats.seconds * 1e-6;
  }
  return f;
}

// The same job on the render worker with no UI at all.
Figures measureWorker(const ViewerOptions& options, std::shared_ptr<const LoadedScene> scene) {
  Figures f;
  const ViewerState state = initialState(options);
  RenderWorker worker;
  OrbitCamera camera(scene->scene);
  const double start = now();
  worker.submit(makeJob(state, scene, camera.pose(), options.width, options.height));
  while (!worker.frame(0) && now() - start < 60.0)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  const double first = now();
  f.firstImage = first - start;
  const uint64_t passes = worker.passesDone();
  std::this_thread::sleep_for(std::chrono::duration<double>(options.benchmarkSeconds));
  f.passesPerSecond = (worker.passesDone() - passes) / (now() - first);
  if (const auto frame = worker.frame(0)) {
    f.spp = frame->stats.samplesPerPixel;
    f.megaRaysPerSecond = frame->stats.counters.totalRays() / frame->stats.seconds * 1e-6;
  }
  return f;
}

struct UiFigures {
  double framesPerSecond = 0.0;
  double worstFrameMs = 0.0;  // the longest gap between two frames: a tap shorter than it is lost
  double megaRaysPerSecond = 0.0;
};

bool hasDisplay() {
  const char* display = std::getenv("DISPLAY");
  return display && *display;
}

// Draws frames back to back, at most 60 a second (a display's rate), while the panes render with
// the render threads on every core at the UI's priority, or as a window has them (`belowUi`:
// render_priority.h), and counts them. Options without a render size give
// the window's size to the panes, as `pathway view` does.
UiFigures measureUi(const ViewerOptions& options, std::shared_ptr<const LoadedScene> scene,
                    bool window, bool belowUi) {
  UiFigures f;
  ViewerState state = initialState(options);
  state.renderBelowUi = belowUi;
  const bool fixed = options.width > 0;
  const int windowWidth =
      fixed ? static_cast<int>(kPanelWidth) + options.width : options.windowWidth;
  const int windowHeight = fixed ? std::max(options.height, 600) : options.windowHeight;
  Viewer viewer(window ? createGlfwPlatform(windowWidth, windowHeight, "Pathway benchmark")
                       : createOsmesaPlatform(windowWidth, windowHeight),
                std::move(state), scene);
  const double start = now();
  while (!viewer.panesCurrent() && now() - start < 60.0) {  // rendering, not starting up
    viewer.frame();
    viewer.waitForChange(true);
  }
  if (options.makeReference) viewer.toggleMakeReference();  // as a demo starts: both render
  const double first = now();
  double last = first;
  int frames = 0;
  while (last - first < options.benchmarkSeconds) {
    viewer.frame();
    ++frames;
    const double t = now();
    f.worstFrameMs = std::max(f.worstFrameMs, (t - last) * 1e3);
    last = t;
    const double next = first + frames / 60.0;
    if (next > t) std::this_thread::sleep_for(std::chrono::duration<double>(next - t));
  }
  f.framesPerSecond = frames / (last - first);
  if (const auto frame = viewer.worker().frame(0))
    f.megaRaysPerSecond = frame->stats.counters.totalRays() / frame->stats.seconds * 1e-6;
  return f;
}

// A demo as the lecturer starts it, headless: seconds from start (scene loaded, viewer made) to
// the first frame showing every pane's first image, and to the first error-plot point (its
// reference asked for then, as the demo does: from the cache when --prepare-demos made it).
struct DemoStart {
  double firstImage = 0.0;
  double errorPlot = 0.0;  // 0: the demo has no plot, or none within the time allowed
  std::string reference;   // where the plot's reference came from
};

DemoStart measureDemoStart(const ViewerOptions& options) {
  DemoStart f;
  const double start = now();
  auto scene = LoadedScene::load(options.choices.scene, options.choices.sceneOptions());
  ViewerState state = initialState(options);
  completeRenderSize(state, scene->scene);  // the demo's width, as `pathway view --demo` has it
  Viewer viewer(createOsmesaPlatform(options.windowWidth, options.windowHeight), std::move(state),
                scene);
  bool referenceAsked = false;
  while (now() - start < 600.0) {
    viewer.frame();
    if (f.firstImage == 0.0 && viewer.panesCurrent() && viewer.imagesShown() > 0) {
      f.firstImage = now() - start;
      if (!options.makeReference) break;
      viewer.toggleMakeReference();
      referenceAsked = true;
    }
    if (referenceAsked && !viewer.errors(0).points().empty()) {
      f.errorPlot = now() - start;
      f.reference = viewer.referenceSource();
      break;
    }
    viewer.waitForChange(true);
  }
  return f;
}

}  // namespace

int runViewerBenchmark(const ViewerOptions& given) {
  ViewerOptions options = given;
  if (options.width <= 0) options.width = 640;
  if (options.height <= 0) options.height = 360;
  options.spp =
      static_cast<uint32_t>(kViewerSamplesPerPixel.maxValue);  // never finishes while measured
  std::vector<std::string> names;
  for (int stage : {1, 3, 5}) {
    if (!findStageIntegrator(stage, Variant::Reference)) continue;
    names.push_back(stageIntegratorName(stage, Variant::Reference));
    const std::string fastest = referenceIntegratorName(stage, ReferenceTracing::Fastest);
    if (fastest != names.back()) names.push_back(fastest);  // what the reference pane shows
  }
  if (names.empty()) names.push_back(setting::kIntegrator);  // a student handout has no references
  auto scene = LoadedScene::load(options.choices.scene, options.choices.sceneOptions());

  std::printf(
      "viewer benchmark: %s, %dx%d render, %u spp per pass, %.1f s each, %u hardware threads\n",
      options.choices.scene.c_str(), options.width, options.height, options.samplesPerPass,
      options.benchmarkSeconds, std::thread::hardware_concurrency());
  std::printf("%-11s | %-31s | %-33s\n", "", "headless viewer (OSMesa UI)", "render worker alone");
  std::printf("%-11s | %8s %8s %6s %6s | %8s %8s %7s %6s\n", "integrator", "first ms", "shown ms",
              "img/s", "UI fps", "first ms", "passes/s", "Mrays/s", "spp");
  for (const std::string& name : names) {
    options.choices.integrator = name;
    const Figures viewer = measureViewer(options, scene);
    const Figures worker = measureWorker(options, scene);
    std::printf("%-11s | %8.1f %8.1f %6.1f %6.1f | %8.1f %8.1f %7.1f %6u\n", name.c_str(),
                viewer.firstImage * 1e3, viewer.firstShown * 1e3, viewer.imagesPerSecond,
                viewer.uiFramesPerSecond, worker.firstImage * 1e3, worker.passesPerSecond,
                worker.megaRaysPerSecond, worker.spp);
    std::printf("%-11s   (viewer: %.1f passes/s, %.1f M rays/s)\n", "", viewer.passesPerSecond,
                viewer.megaRaysPerSecond);
    std::fflush(stdout);
  }
  std::printf(
      "first ms: submit -> first developed image; shown ms: viewer start (GL context, "
      "fonts, worker) -> first frame showing it; img/s: new images the panes showed\n");

  const bool window = hasDisplay();
  const int besideUi = renderThreadsBesideUi(std::thread::hardware_concurrency());
  std::printf("\nUI while rendering (%s, frames drawn back to back, at most 60/s):\n",
              window ? "GLFW window" : "OSMesa, no display");
  char below[64];
  std::snprintf(below, sizeof below, "as a window: %d thread%s, nice 10", std::max(besideUi, 1),
                besideUi > 1 ? "s" : "");
  std::printf("%-15s | %-29s | %-29s\n", "", "every core, UI's priority", below);
  std::printf("%-15s | %7s %10s %9s | %7s %10s %9s\n", "integrator/demo", "UI fps", "worst ms",
              "Mrays/s", "UI fps", "worst ms", "Mrays/s");
  for (const std::string& name : names) {
    options.choices.integrator = name;
    const UiFigures all = measureUi(options, scene, window, false);
    const UiFigures fewer = measureUi(options, scene, window, true);
    std::printf("%-15s | %7.1f %10.1f %9.1f | %7.1f %10.1f %9.1f\n", name.c_str(),
                all.framesPerSecond, all.worstFrameMs, all.megaRaysPerSecond, fewer.framesPerSecond,
                fewer.worstFrameMs, fewer.megaRaysPerSecond);
    std::fflush(stdout);
  }
  // The lecture's split demos as they start: a 1280 x 720 window, panes following it, the error
  // plot's reference being made beside them.
  for (const ViewerDemo& demo : viewerDemos()) {
    if (demo.splitIntegrator.empty()) continue;
    ViewerOptions demoOptions = given;
    applyViewerDemo(demo.name, demoOptions);
    demoOptions.width = demoOptions.height = 0;
    // The reference is made beside the panes (a demo without --prepare-demos), and not kept.
    demoOptions.cacheReferences = false;
    auto demoScene =
        LoadedScene::load(demoOptions.choices.scene, demoOptions.choices.sceneOptions());
    const UiFigures all = measureUi(demoOptions, demoScene, window, false);
    const UiFigures fewer = measureUi(demoOptions, demoScene, window, true);
    std::printf("%-15s | %7.1f %10.1f %9.1f | %7.1f %10.1f %9.1f\n", demo.name.c_str(),
                all.framesPerSecond, all.worstFrameMs, all.megaRaysPerSecond, fewer.framesPerSecond,
                fewer.worstFrameMs, fewer.megaRaysPerSecond);
    std::fflush(stdout);
  }
  std::printf(
      "worst ms: the longest frame; a key tapped for less than it was lost before key "
      "presses were queued. Demos: %dx%d window, split panes following it, their "
      "reference being made\n",
      given.windowWidth, given.windowHeight);

  // Ready for class: each demo as `pathway view --demo` starts it (its own render size, the
  // reference cache on).
  std::printf("\nDemos as they start (headless, %dx%d window):\n", given.windowWidth,
              given.windowHeight);
  std::printf("%-16s | %14s | %15s | %s\n", "demo", "first image s", "error plot s",
              "the plot's reference");
  for (const ViewerDemo& demo : viewerDemos()) {
    ViewerOptions demoOptions = given;
    applyViewerDemo(demo.name, demoOptions);
    const DemoStart f = measureDemoStart(demoOptions);
    char plot[32] = "-";
    if (demo.makeReference)
      std::snprintf(plot, sizeof plot, f.errorPlot > 0.0 ? "%.2f" : "none", f.errorPlot);
    std::printf("%-16s | %14.2f | %15s | %s\n", demo.name.c_str(), f.firstImage, plot,
                f.reference.c_str());
    std::fflush(stdout);
  }
  std::printf(
      "first image: start -> a frame showing every pane's first image; error plot: start -> "
      "its first point (run `pathway view --prepare-demos` first, or the reference is made "
      "on the spot)\n");
  return 0;
}

}  // namespace pathway
