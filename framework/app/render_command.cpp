// `pathway render [scene] [options]`: render a scene with one integrator and write EXR and/or PNG.
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/launch_clock.h"
#include "app/progress_bar.h"
#include "app/shared_options.h"
#include "core/error.h"
#include "engine/render_session.h"
#include "io/partial_film.h"
#include "io/raster_files.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

struct RenderOptions {
  RenderChoices choices;
  std::vector<std::string> outputs = {"render.png"};
  // Their defaults and ranges: the declarations they are added from (run() sees them filled in).
  int width = 0;
  int height = 0;  // not given: from the scene camera's aspect ratio, else square
  uint32_t spp = 0;
  int threads = 0;
  float exposure = 0.0f;
  bool list = false;
  bool quiet = false;
  bool timings = false;
  bool checkOnly = false;
  std::string samples;  // "A:B": only sample indices [A, B) of the --spp, written as a part
};

void listIntegrators() {
  std::printf("Integrators (choose with --integrator NAME, set parameters with -p name=value):\n");
  for (const IntegratorInfo* info : allIntegrators()) {
    std::printf("\n  %-12s stage %d, %s, sampler %s: %s\n", info->name.c_str(), info->stage,
                variantName(info->variant), samplerTypeName(info->defaultSampler).c_str(),
                info->summary.c_str());
    for (const OptionSpec& spec : info->params)
      std::printf(
          "      %-16s %s (default %s, %s %s)\n", spec.name.c_str(), spec.help.c_str(),
          spec.format(spec.defaultValue).c_str(),
          spec.kind == OptionKind::Integer || spec.kind == OptionKind::Real ? "range" : "choose",
          spec.describeRange().c_str());
  }
}

int run(const RenderOptions& options, const LaunchClock& clock) {
  if (options.list) {
    listIntegrators();
    return 0;
  }
  // Check everything that can be checked before the scene is loaded and rendering starts.
  RenderRecipe recipe = options.choices.recipe();
  RenderSettings& s = recipe.settings;
  s.samplesPerPixel = options.spp;
  s.threads = options.threads;
  if (!options.samples.empty() && !parseSampleRange(options.samples, s.sampleBegin, s.sampleEnd))
    throw PathwayError("--samples '" + options.samples +
                       "': expected A:B with A < B (sample indices)");
  // Where the CLI's settings enter: a range that is not part of --spp is refused before the
  // scene loads (the others CLI11 checks as it reads them).
  s.check();
  s.samplesPerPass = samplesPerProgressPass(s.samplesToRender());
  for (const std::string& output : options.outputs) checkImagePath(output);

  const double startMs = clock.milliseconds();
  const Scene scene = loadScene(options.choices.scene, options.choices.sceneOptions());
  const double sceneMs = clock.milliseconds();
  s.width = options.width;
  s.height = options.height;
  if (s.height == 0) s.height = scene.imageHeight(options.width);
  const RayTracer tracer(scene);
  const double bvhMs = clock.milliseconds();
  double firstRayMs = 0.0;
  if (options.checkOnly) {
    const Camera camera(scene, s.width, s.height);
    const RenderSession session(tracer, camera, recipe);  // checks the integrator and parameters
    std::printf("checked: %s, %s, %dx%d, samples %u:%u of %u\n", options.choices.scene.c_str(),
                recipe.integrator.c_str(), s.width, s.height, s.firstSample(), s.endSample(),
                s.samplesPerPixel);
    return 0;
  }

  ProgressBar progress(!options.quiet);
  const Camera camera(scene, s.width, s.height);
  RenderSession session(tracer, camera, recipe);
  session.renderer().renderAll([&](const RenderStats& stats) {
    if (firstRayMs == 0.0) firstRayMs = clock.milliseconds() - stats.seconds * 1e3;
    const std::string label =
        std::to_string(stats.samplesPerPixel) + "/" + std::to_string(s.samplesToRender()) + " spp";
    progress.update(static_cast<double>(stats.samplesPerPixel) / s.samplesToRender(),
                    label.c_str());
  });
  progress.finish();
  const RenderResult result = session.develop();

  const double renderedMs = clock.milliseconds();
  for (const std::string& output : options.outputs) {
    // A part carries the film's sums, for `pathway merge`.
    if (!options.samples.empty() && lowerExtension(output) == ".exr")
      writePartialFilm(output, session.renderer().film(), result.images, result.metadata);
    else
      writeImageFile(output, result.images, result.metadata, options.exposure);
  }
  if (options.timings)
    std::printf(
        "timings (ms %s): command starts %.1f, scene read %.1f, BVH built %.1f, first ray %.1f, "
        "last ray %.1f, images written %.1f\n",
        clock.origin(), startMs, sceneMs, bvhMs, firstRayMs, renderedMs, clock.milliseconds());

  const RayCounters& c = result.stats.counters;
  const double seconds = result.stats.seconds;
  if (!options.quiet) {
    std::printf("%s: %s, %dx%d, %u spp, %.3f s\n", options.choices.scene.c_str(),
                recipe.integrator.c_str(), s.width, s.height, result.stats.samplesPerPixel,
                seconds);
    std::printf("rays: %llu primary, %llu secondary, %llu shadow; %.2f M rays/s\n",
                static_cast<unsigned long long>(c.primary),
                static_cast<unsigned long long>(c.secondary),
                static_cast<unsigned long long>(c.shadow), c.totalRays() / seconds * 1e-6);
  }
  if (c.invalidSamples > 0)
    std::fprintf(stderr, "pathway: warning: %llu non-finite samples were dropped\n",
                 static_cast<unsigned long long>(c.invalidSamples));
  if (result.unresolvedPixels > 0)
    std::fprintf(stderr,
                 "pathway: warning: %zu pixels have filter weights summing to about 0 "
                 "(negative lobes at low spp); they are written as 0\n",
                 result.unresolvedPixels);
  if (!result.todos.empty())
    std::fprintf(stderr,
                 "pathway: note: %zu TODO(s) in the stage code ran; this image uses "
                 "placeholders\n",
                 result.todos.size());
  for (const std::string& output : options.outputs) std::printf("wrote %s\n", output.c_str());
  return 0;
}

}  // namespace

Command addRenderCommand(CLI::App& app) {
  auto options = std::make_shared<RenderOptions>();
  options->choices.scene = PATHWAY_DEFAULT_SCENE;
  CLI::App* render = app.add_subcommand("render", "Render a scene to an image file");
  render->footer(
      "Examples:\n"
      "  pathway render --list                          integrators and their parameters\n"
      "  pathway render scenes/cornell_box.gltf -o box.png\n"
      "  pathway render scenes/cornell_box.gltf -i stage1@ref --filter mitchell --spp 4 -o a.exr\n"
      "  pathway render scenes/cornell_box.gltf -i stage2 -p ao-rays=4 -p ao-distance=0.3\n"
      "  pathway render scenes/cornell_box.gltf -i stage5@ref -p nee=off -p light-pick=area\n"
      "  pathway render scenes/cornell_box.gltf --spp 64 --samples 0:32 -o part0.exr   (merge)");
  addSharedOptions(*render, options->choices);
  render
      ->add_option("-o,--output", options->outputs,
                   "Output file(s): .exr (linear, variance, metadata) or .png (sRGB)")
      ->capture_default_str();
  addOption(*render, setting::kSamplesPerPixel, options->spp);
  addOption(*render, setting::kWidth, options->width);
  addOptionWorkedOut(*render, setting::kHeight, options->height, "from the camera's aspect ratio");
  addOption(*render, setting::kThreads, options->threads);
  addOption(*render, setting::kExposure, options->exposure);
  render->add_option("--samples", options->samples,
                     "Render only sample indices A:B of the --spp (a part: .exr outputs carry the "
                     "film's sums, for pathway merge)");
  render->add_flag("--check", options->checkOnly,
                   "Check the options, the scene and the outputs' folders; render nothing");
  render->add_flag("--list", options->list, "List the integrators and their parameters, then exit");
  render->add_flag("-q,--quiet", options->quiet, "No progress bar or summary");
  render->add_flag("--timings", options->timings,
                   "Print when each step ended (ms since launch: see pathway_bench startup)");
  // Started here, as early as the program can: the clock of --timings.
  auto clock = std::make_shared<LaunchClock>();
  return {render, [options, clock] { return run(*options, *clock); }};
}

}  // namespace pathway
