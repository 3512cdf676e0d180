#include "fast.h"

#include <tbb/info.h>

#include <cmath>
#include <cstdio>
#include <cstring>

#include "bench_kit.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "scene/gltf_loader.h"
#include "spawn.h"

namespace pathway::bench {
namespace {

glm::dvec3 meanOf(const Image& image) {
  glm::dvec3 sum(0.0);
  for (const Color& c : image.pixels) sum += glm::dvec3(c);
  return sum / double(image.pixels.size());
}

bool sameBits(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

// The largest relative difference of the channel means.
double meanDifference(const Image& a, const Image& b) {
  const glm::dvec3 ma = meanOf(a), mb = meanOf(b);
  double worst = 0.0;
  for (int c = 0; c < 3; ++c) worst = std::max(worst, std::fabs(ma[c] - mb[c]) / std::fabs(mb[c]));
  return worst;
}

struct Pair {
  double single = 1e30, fast = 1e30;  // best seconds
  RenderResult singleResult, fastResult;
};

// Both renders of `stage`, `repeats` times in turns.
Pair timeInTurns(const RayTracer& tracer, int stage, int width, int height, uint32_t spp,
                 int repeats) {
  auto recipe = [&](ReferenceTracing tracing) {
    return RenderRecipe(RecipeBuilder(referenceIntegratorName(stage, tracing))
                            .size(width, height)
                            .spp(spp, samplesPerProgressPass(spp))
                            .filter(FilterType::Box));
  };
  const RenderRecipe single = recipe(ReferenceTracing::SingleRay);
  const RenderRecipe fast = recipe(ReferenceTracing::Fastest);
  Pair pair;
  for (int i = 0; i < repeats; ++i) {
    pair.single =
        std::min(pair.single, secondsOf([&] { pair.singleResult = runRender(tracer, single); }));
    pair.fast = std::min(pair.fast, secondsOf([&] { pair.fastResult = runRender(tracer, fast); }));
  }
  return pair;
}

// A `pathway` command's wall seconds; throws when it fails.
double commandSeconds(std::vector<std::string> arguments) {
  arguments.insert(arguments.begin(), PATHWAY_PROGRAM);
  const SpawnedRun run = spawnCapturingStdout(arguments);
  if (!run.outcome.succeeded()) throw PathwayError(arguments[1] + " " + arguments[2] + " failed");
  return run.seconds;
}

}  // namespace

int benchFast(const FastOptions& options) {
  const Scene scene = loadScene(options.scene);
  const RayTracer tracer(scene);
  const int width = options.width, height = scene.imageHeight(width);
  std::printf(
      "fast: %s, %dx%d, %u spp, box filter, each stage's default parameters and sampler, %d "
      "threads;\nseconds: the whole render in this process, best of %d, single-ray and "
      "wavefront in turns; load average %.2f at the start\n\n",
      options.scene.c_str(), width, height, options.samplesPerPixel,
      tbb::info::default_concurrency(), options.repeats, loadAverage());
  std::printf("%-8s %12s %12s %16s %14s %14s\n", "stage", "@ref s", "@fast s", "@fast / @ref",
              "same bits", "mean diff");
  int status = 0;
  for (int stage : {1, 2, 3, 5}) {
    if (referenceIntegratorName(stage, ReferenceTracing::Fastest) ==
        referenceIntegratorName(stage, ReferenceTracing::SingleRay))
      throw PathwayError("stage " + std::to_string(stage) + " has no wavefront version here");
    const Pair pair =
        timeInTurns(tracer, stage, width, height, options.samplesPerPixel, options.repeats);
    const double difference =
        meanDifference(pair.fastResult.images.color, pair.singleResult.images.color);
    if (difference > 1e-3) status = 1;
    std::printf(
        "stage%-3d %12.3f %12.3f %16.3f %14s %13.5f%%\n", stage, pair.single, pair.fast,
        pair.fast / pair.single,
        sameBits(pair.fastResult.images.color, pair.singleResult.images.color) ? "yes" : "no",
        100.0 * difference);
    std::fflush(stdout);
  }

  // The mean at high spp, and at another seed (noise alone then separates the two).
  {
    const int w = 64, h = scene.imageHeight(w);
    auto render = [&](const char* integrator, uint64_t seed) {
      return runRender(tracer,
                       RecipeBuilder(integrator)
                           .size(w, h)
                           .spp(options.agreementSpp, samplesPerProgressPass(options.agreementSpp))
                           .seed(seed))
          .images.color;
    };
    const Image single = render("stage5@ref", 1), fast = render("stage5@fast", 1),
                other = render("stage5@fast", 2);
    const double same = meanDifference(fast, single), seeds = meanDifference(other, single);
    if (same > 1e-3) status = 1;
    std::printf(
        "\nstage 5 mean, %dx%d at %u spp: stage5@fast vs stage5@ref, same seed %.5f%% (bits %s); "
        "stage5@fast at another seed %.5f%%\n",
        w, h, options.agreementSpp, 100.0 * same, sameBits(fast, single) ? "identical" : "differ",
        100.0 * seeds);
  }

  // The commands that render references, whole processes, in turns.
  const TemporaryFolder folder("pathway-bench-fast");
  const std::string references = folder.path() + "/references";
  std::printf("\n%-44s %12s %12s %10s\n", "command (whole process, wall)", "--single-ray s",
              "default s", "ratio");
  auto row = [](const std::string& what, const std::vector<std::string>& arguments) {
    std::vector<std::string> single = arguments;
    single.push_back("--single-ray");
    const double singleSeconds = commandSeconds(single);
    const double fastSeconds = commandSeconds(arguments);
    std::printf("%-44s %12.2f %12.2f %10.3f\n", what.c_str(), singleSeconds, fastSeconds,
                fastSeconds / singleSeconds);
    std::fflush(stdout);
  };
  for (int stage : {1, 2, 3, 5})
    row("grade --make-references --stage " + std::to_string(stage),
        {"grade", "--make-references", "--stage", std::to_string(stage), "--references", references,
         "-q"});
  row("grade --make-references (every case)",
      {"grade", "--make-references", "--references", references, "-q"});
  if (options.calibrationSeeds > 0)
    row("grade --grade-reference --calibrate " + std::to_string(options.calibrationSeeds),
        {"grade", "--grade-reference", "--calibrate", std::to_string(options.calibrationSeeds)});
  std::printf("ratio: default (stageN@fast where it exists) / --single-ray (stageN@ref)\n");
  return status;
}

}  // namespace pathway::bench
