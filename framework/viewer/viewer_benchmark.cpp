// `pathway view --benchmark`: how fast the progressive display is, measured headless (OSMesa) on
// the real viewer, and the render worker alone for comparison. Prints one row per integrator.
#include <chrono>
#include <cstdio>
#include <thread>

#include "render/integrator_registry.h"
#include "viewer/viewer_app.h"

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
  auto scene = LoadedScene::load(options.choices.scene, {options.choices.strictScene});

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
  return 0;
}

}  // namespace pathway
