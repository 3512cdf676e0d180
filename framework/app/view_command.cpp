// `pathway view [scene] [options]`: the interactive viewer (framework/viewer/), or the same viewer
// drawn offscreen with --headless for screenshots and benchmarks. Built only with the viewer.
#ifdef PATHWAY_HAS_VIEWER
#include <cstdio>
#include <memory>

#include "app/commands.h"
#include "app/shared_options.h"
#include "viewer/reference_cache.h"
#include "viewer/viewer_app.h"
#include "viewer/viewer_demos.h"

namespace pathway {

Command addViewCommand(CLI::App& app) {
  auto options = std::make_shared<ViewerOptions>();
  auto demo = std::make_shared<std::string>();
  auto listDemos = std::make_shared<bool>(false);
  auto prepareDemos = std::make_shared<bool>(false);
  options->choices.scene = PATHWAY_DEFAULT_SCENE;
  CLI::App* view = app.add_subcommand("view", "Open the interactive viewer");
  view->footer(
      "Examples:\n"
      "  pathway view                                    Cornell box, stage 1 (yours)\n"
      "  pathway view scenes/cornell_box.gltf -i stage2 -p ao-rays=4\n"
      "  pathway view -i stage5@ref -p nee=on --split stage5@ref --split-param nee=off --balance "
      "rays\n"
      "  pathway view --headless --frames 60 --screenshot ui.png   (no display needed)\n"
      "  pathway view -i stage5@ref --width 512 --height 512 --reference ref.exr   error plot\n"
      "  pathway view --benchmark                        progressive fps, time to first image\n"
      "  pathway view --demo nested-vs-4d                a lecture demo (--list-demos)\n"
      "Press H in the viewer for the keys and mouse.");
  addSharedOptions(*view, options->choices);
  view->add_option("--split", options->splitIntegrator,
                   "Split view: this integrator in the right pane");
  view->add_option("--split-param", options->splitParams,
                   "Parameter name=value of the right pane's integrator (repeatable)");
  view->add_option("--split-sampler", options->splitSampler,
                   "Split view: the right pane's own sampler (default: the left pane's)")
      ->check(CLI::IsMember(samplerTypeNames()));
  view->add_option("--split-filter", options->splitFilter,
                   "Split view: the right pane's own pixel filter (default: the left pane's)")
      ->check(CLI::IsMember(filterTypeNames()));
  view->add_option("--balance", options->balance,
                   "Split view: 'time' (equal render time) or 'rays' (equal ray count)")
      ->capture_default_str();
  addOptionWorkedOut(*view, setting::kWidth, options->width, "follow the window");
  addOptionWorkedOut(*view, setting::kHeight, options->height, "follow the window");
  view->add_option("--window-width", options->windowWidth, "Window width")
      ->check(CLI::Range(400, 16384))
      ->capture_default_str();
  view->add_option("--window-height", options->windowHeight, "Window height")
      ->check(CLI::Range(300, 16384))
      ->capture_default_str();
  addOption(*view, kViewerSamplesPerPixel, options->spp);
  addOption(*view, setting::kSamplesPerPass, options->samplesPerPass);
  addOption(*view, setting::kExposure, options->exposure);
  view->add_option("--display", options->display, "color, variance or rays (rays per sample)")
      ->capture_default_str();
  addOption(*view, kScaleTop, options->scaleTop);
  view->add_flag("--show-help", options->showHelp, "Open with the keys-and-mouse help shown");
  view->add_flag("--headless", options->headless,
                 "Draw the viewer offscreen (OSMesa): no display needed");
  view->add_option("--frames", options->frames,
                   "Draw this many frames, then exit (headless default: 30)")
      ->check(CLI::Range(1, 1000000));
  view->add_option("--screenshot", options->screenshot,
                   "After the last frame, write the whole window (panel included) to this PNG");
  view->add_flag("--grade", options->grade,
                 "Grade the left pane against the reference once its first image is in (key G)");
  view->add_option("--reference", options->reference,
                   "An EXR of the scene's camera view at the render size (--width/--height): the "
                   "error plot measures relMSE against it");
  addOption(*view, setting::kReferenceSamplesPerPixel, options->referenceSpp);
  view->add_flag("--make-reference", options->makeReference,
                 "Make the error plot's reference once the first image is in (key M)");
  view->add_flag("--benchmark", options->benchmark,
                 "Measure progressive frames per second and time to first image (headless)");
  view->add_option("--benchmark-seconds", options->benchmarkSeconds,
                   "How long each benchmark measurement runs")
      ->check(CLI::Range(0.2, 600.0))
      ->capture_default_str();
  view->add_option("--demo", *demo,
                   "Start a lecture demo by name: its scene, integrators, split view, balance and "
                   "display (see --list-demos)");
  view->add_flag("--list-demos", *listDemos, "List the lecture demos, then exit");
  view->add_flag("--prepare-demos", *prepareDemos,
                 "Before class: make every demo's error-plot reference once and keep it (in "
                 "$XDG_CACHE_HOME/pathway/references), so each demo's plot starts at once");
  return {view, [options, demo, listDemos, prepareDemos] {
            if (*listDemos) {
              for (const ViewerDemo& d : viewerDemos())
                // The keys as a shell comment on the command's line: the line still runs when
                // pasted, and scripts/slides reads the demo names from the other lines.
                std::printf("%-16s %s\n%16s pathway view %s   # keys: %s\n", d.name.c_str(),
                            d.shows.c_str(), "", describeViewerDemo(d).c_str(), d.keys.c_str());
              return 0;
            }
            if (*prepareDemos) {
              for (const ViewerDemo& d : viewerDemos()) {
                if (!d.makeReference) continue;
                ViewerOptions prepared = *options;
                applyViewerDemo(d.name, prepared);
                prepared.headless = true;
                prepared.frames = 1;
                prepared.prepareReference = true;
                std::printf("%s: ", d.name.c_str());
                std::fflush(stdout);
                if (const int status = runViewer(prepared); status != 0) return status;
              }
              std::printf("references kept in %s\n", referenceCacheFolder().string().c_str());
              return 0;
            }
            if (!demo->empty()) applyViewerDemo(*demo, *options);
            return runViewer(*options);
          }};
}

}  // namespace pathway
#endif  // PATHWAY_HAS_VIEWER
