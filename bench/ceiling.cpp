#include "ceiling.h"

#include <tbb/info.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "bench_kit.h"
#include "engine/render_choices.h"
#include "raw_path_tracer.h"
#include "scene/gltf_loader.h"
#include "stages/stage5.h"

namespace pathway::bench {
namespace {

// The global means must agree to 1 % per channel, or to 4 standard errors of their difference
// where noise alone makes that larger (small images, few samples).
constexpr double kMeanTolerance = 0.01;
constexpr double kMeanStandardErrors = 4.0;
constexpr int kRegionSide = 16;  // pixels per side of the regions compared

glm::dvec3 meanOf(const std::vector<Color>& pixels) {
  glm::dvec3 sum(0.0);
  for (const Color& c : pixels) sum += glm::dvec3(c);
  return sum / static_cast<double>(pixels.size());
}

// How two images of the same size differ region by region. Different random numbers make them
// differ by noise everywhere; a bias (a missed term, a wrong pdf) shows as a region that differs
// far more than its noise allows.
struct RegionDifference {
  double relative = 0.0;  // the largest |mean a - mean b| / their average, of (R + G + B) / 3
  int x = 0, y = 0;       // its region's top-left pixel
  double mean = 0.0;      // its region's mean of (R + G + B) / 3
  double z = 0.0;         // the largest |mean a - mean b| / its standard error, over channels
  int zx = 0, zy = 0;     // its region's top-left pixel
};

// `variance`: of each pixel's estimate, in a and b alike (the framework's variance image; both
// images are the same estimator at the same spp). Relative differences are largest where the
// image is dark or straddles the light's edge; z weighs each difference by the noise it has.
RegionDifference compareRegions(const std::vector<Color>& a, const std::vector<Color>& b,
                                const std::vector<Color>& variance, int width, int height) {
  RegionDifference worst;
  for (int y0 = 0; y0 < height; y0 += kRegionSide) {
    for (int x0 = 0; x0 < width; x0 += kRegionSide) {
      glm::dvec3 sumA(0.0), sumB(0.0), sumVariance(0.0);
      for (int y = y0; y < std::min(height, y0 + kRegionSide); ++y) {
        for (int x = x0; x < std::min(width, x0 + kRegionSide); ++x) {
          const size_t i = static_cast<size_t>(y) * width + x;
          sumA += glm::dvec3(a[i]);
          sumB += glm::dvec3(b[i]);
          sumVariance += glm::dvec3(variance[i]);
        }
      }
      const double totalA = sumA.x + sumA.y + sumA.z, totalB = sumB.x + sumB.y + sumB.z;
      const double average = 0.5 * (totalA + totalB);
      const double relative = average > 0.0 ? std::fabs(totalA - totalB) / average : 0.0;
      if (relative > worst.relative) {
        const int pixels =
            (std::min(height, y0 + kRegionSide) - y0) * (std::min(width, x0 + kRegionSide) - x0);
        worst.relative = relative, worst.x = x0, worst.y = y0;
        worst.mean = average / (3.0 * pixels);
      }
      for (int c = 0; c < 3; ++c) {
        // The difference of two independent sums, each with variance sumVariance.
        const double error = std::sqrt(2.0 * sumVariance[c]);
        const double z = error > 0.0 ? std::fabs(sumA[c] - sumB[c]) / error : 0.0;
        if (z > worst.z) worst.z = z, worst.zx = x0, worst.zy = y0;
      }
    }
  }
  return worst;
}

void printRegions(const char* label, const RegionDifference& d) {
  std::printf("  %-32s %6.2f %% at (%3d, %3d), mean %.4f; largest z %.2f at (%3d, %3d)\n", label,
              100.0 * d.relative, d.x, d.y, d.mean, d.z, d.zx, d.zy);
}

void printRow(const char* name, double seconds, const RayCounters& rays, double samples) {
  std::printf("%-32s %8.3f %12llu %12.3f %9.2f %11llu %11llu %11llu\n", name, seconds,
              static_cast<unsigned long long>(rays.totalRays()), rays.totalRays() / samples,
              rays.totalRays() / seconds * 1e-6, static_cast<unsigned long long>(rays.primary),
              static_cast<unsigned long long>(rays.secondary),
              static_cast<unsigned long long>(rays.shadow));
}

}  // namespace

int benchCeiling(const CeilingOptions& options) {
  const Scene scene = loadScene(options.scene);
  const RayTracer tracer(scene);
  const RawEmbree embree(scene);  // a BVH of its own, built with the same flags
  const RawPathTracer raw(scene, embree);
  const int width = options.width, height = scene.imageHeight(width);
  const uint32_t spp = options.samplesPerPixel;
  const Camera camera(scene, width, height);

  // The framework's side as `pathway render` builds it: choices, built into a recipe, run through
  // a session. light-pick=area is the estimator the raw tracer implements (stage 5's
  // default is power; the two are the same when every emitter has the same radiance).
  RenderChoices choices;
  choices.scene = options.scene;
  choices.integrator = "stage5@ref";
  choices.params = {"light-pick=area"};
  const RenderRecipe recipe =  // in passes as `pathway render` makes them
      choices.builder().size(width, height).spp(spp, samplesPerProgressPass(spp));

  // The raw side takes stage 5's depths from the same checked recipe: they cannot drift apart.
  RawPathSettings rawSettings;
  rawSettings.width = width;
  rawSettings.height = height;
  rawSettings.samplesPerPixel = spp;
  const Stage5Params stage5Params = stage5().read(recipe.params);
  rawSettings.maxDepth = stage5Params.maxDepth;
  rawSettings.rouletteDepth = stage5Params.rouletteDepth;
  rawSettings.seed = recipe.settings.seed;

  std::printf(
      "ceiling: %s, %dx%d, %u spp, max-depth %d, rr-depth %d, NEE, light-pick area, %d threads\n"
      "raw: bench/raw_path_tracer.cpp on rtcIntersect1/rtcOccluded1, all spp per pixel at once;\n"
      "framework: stage5@ref through RenderSession, %u spp per pass (as `pathway render`);\n"
      "seconds: the whole render to an image, best of %d, raw and framework in turns\n"
      "load average %.2f at the start (other processes lower the framework's ratio more than the\n"
      "raw tracer's: compare runs made at similar load)\n\n",
      options.scene.c_str(), width, height, spp, rawSettings.maxDepth, rawSettings.rouletteDepth,
      tbb::info::default_concurrency(), recipe.settings.samplesPerPass, options.repeats,
      loadAverage());
  for (const Material& material : scene.materials)
    if (material.baseColorTexture >= 0) {
      std::printf("note: the raw tracer ignores textures; this scene has some\n\n");
      break;
    }

  // Stage 5 renders with Owen-scrambled Sobol' by default, which costs more per sample than one
  // PCG32 per pixel. Two pairs compute the same estimator: stage 5 (Sobol') against the raw
  // tracer drawing the same Sobol' numbers, and stage 5 with the independent sampler against the
  // raw tracer with PCG32.
  RenderRecipe independentRecipe = recipe;
  independentRecipe.settings.sampler = SamplerType::Independent;

  RawPathSettings rawSobolSettings = rawSettings;
  rawSobolSettings.sobol = true;

  // Both renderers are deterministic: every repeat makes the same image with the same rays.
  RawPathImage rawImage, rawSobolImage;
  RenderResult framework, independent;
  double rawSeconds = 1e30, rawSobolSeconds = 1e30, frameworkSeconds = 1e30, passSeconds = 1e30;
  double independentSeconds = 1e30;
  for (int i = 0; i < options.repeats; ++i) {
    rawSeconds =
        std::min(rawSeconds, secondsOf([&] { rawImage = raw.render(camera, rawSettings); }));
    rawSobolSeconds = std::min(
        rawSobolSeconds, secondsOf([&] { rawSobolImage = raw.render(camera, rawSobolSettings); }));
    frameworkSeconds = std::min(frameworkSeconds,
                                secondsOf([&] { framework = runRender(tracer, camera, recipe); }));
    passSeconds = std::min(passSeconds, framework.stats.seconds);
    independentSeconds =
        std::min(independentSeconds,
                 secondsOf([&] { independent = runRender(tracer, camera, independentRecipe); }));
  }
  const RayCounters& rawRays = rawImage.rays;
  const RayCounters& frameworkRays = framework.stats.counters;

  const double samples = double(width) * height * spp;
  std::printf("%-32s %8s %12s %12s %9s %11s %11s %11s\n", "", "seconds", "rays", "rays/sample",
              "Mrays/s", "primary", "secondary", "shadow");
  printRow("raw Embree path tracer (PCG32)", rawSeconds, rawRays, samples);
  printRow("raw Embree path tracer (Sobol')", rawSobolSeconds, rawSobolImage.rays, samples);
  printRow("stage5@ref (Sobol', its default)", frameworkSeconds, frameworkRays, samples);
  printRow("  its passes alone", passSeconds, frameworkRays, samples);
  printRow("stage5@ref sampler=independent", independentSeconds, independent.stats.counters,
           samples);
  const double rawRate = rawRays.totalRays() / rawSeconds;
  const double rawSobolRate = rawSobolImage.rays.totalRays() / rawSobolSeconds;
  const double frameworkRate = frameworkRays.totalRays() / frameworkSeconds;
  const double independentRate = independent.stats.counters.totalRays() / independentSeconds;
  std::printf(
      "framework / raw, Mrays/s (goal >= 0.85), same numbers: Sobol' %.3f, independent / PCG32 "
      "%.3f\n"
      "stage5@ref (Sobol') / raw (PCG32): Mrays/s %.3f, wall time %.3f\n\n",
      frameworkRate / rawSobolRate, independentRate / rawRate, frameworkRate / rawRate,
      frameworkSeconds / rawSeconds);

  // The images: the same expected value, different random numbers. Another seed of the raw
  // tracer shows how far two images differ by noise alone.
  RawPathSettings otherSeed = rawSettings;
  otherSeed.seed = rawSettings.seed + 1;
  const RawPathImage rawAgain = raw.render(camera, otherSeed);
  const std::vector<Color>& frameworkPixels = framework.images.color.pixels;
  const glm::dvec3 rawMean = meanOf(rawImage.pixels), frameworkMean = meanOf(frameworkPixels);
  const std::vector<Color>& variance = framework.images.variance.pixels;
  // Relative to the raw mean; a channel black in both (a scene without light) differs by 0.
  auto relative = [&](const glm::dvec3& value) {
    glm::dvec3 r;
    for (int c = 0; c < 3; ++c) r[c] = value[c] == 0.0 ? 0.0 : value[c] / rawMean[c];
    return r;
  };
  const glm::dvec3 difference = relative(frameworkMean - rawMean);
  // The standard error of the difference of two independent images' means.
  const double pixels = static_cast<double>(frameworkPixels.size());
  const glm::dvec3 error = relative(glm::sqrt(2.0 * meanOf(variance) / pixels));
  const glm::dvec3 limit = glm::max(glm::dvec3(kMeanTolerance), kMeanStandardErrors * error);
  const bool meansAgree = std::fabs(difference.x) <= limit.x &&
                          std::fabs(difference.y) <= limit.y && std::fabs(difference.z) <= limit.z;
  std::printf("image agreement (different random numbers)      R          G          B\n");
  std::printf("  global mean, raw                        %10.5f %10.5f %10.5f\n", rawMean.x,
              rawMean.y, rawMean.z);
  std::printf("  global mean, framework                  %10.5f %10.5f %10.5f\n", frameworkMean.x,
              frameworkMean.y, frameworkMean.z);
  std::printf("  framework vs raw                        %+9.2f%% %+9.2f%% %+9.2f%%  %s\n",
              100.0 * difference.x, 100.0 * difference.y, 100.0 * difference.z,
              meansAgree ? "ok" : "FAIL");
  std::printf("  limit: 1 %%, or 4 standard errors     %9.2f%% %9.2f%% %9.2f%%\n", 100.0 * limit.x,
              100.0 * limit.y, 100.0 * limit.z);
  std::printf("  worst %dx%d region (of %d x %d), relative and in standard errors (z):\n",
              kRegionSide, kRegionSide, (width + kRegionSide - 1) / kRegionSide,
              (height + kRegionSide - 1) / kRegionSide);
  printRegions("framework vs raw",
               compareRegions(rawImage.pixels, frameworkPixels, variance, width, height));
  printRegions("raw vs raw, another seed (noise)",
               compareRegions(rawImage.pixels, rawAgain.pixels, variance, width, height));

  // With the same Sobol' numbers, the two tracers follow the same paths: their images differ
  // only where float rounding in a different order tips a comparison (roulette, a grazing
  // shadow ray) and a path goes another way.
  const glm::dvec3 sameNumbersDifference = relative(frameworkMean - meanOf(rawSobolImage.pixels));
  size_t differentPixels = 0;
  for (size_t i = 0; i < frameworkPixels.size(); ++i) {
    const Color a = frameworkPixels[i], b = rawSobolImage.pixels[i];
    const float scale = std::max({maxComponent(a), maxComponent(b), 1e-3f});
    if (maxComponent(glm::abs(a - b)) > 1e-3f * scale) ++differentPixels;
  }
  const bool sameNumbersAgree =
      glm::all(glm::lessThanEqual(glm::abs(sameNumbersDifference), glm::dvec3(kMeanTolerance)));
  std::printf(
      "same Sobol' numbers: global means %+.3f%% %+.3f%% %+.3f%%  %s; %zu of %zu pixels differ by "
      "more than 0.1 %%\n",
      100.0 * sameNumbersDifference.x, 100.0 * sameNumbersDifference.y,
      100.0 * sameNumbersDifference.z, sameNumbersAgree ? "ok" : "FAIL", differentPixels,
      frameworkPixels.size());
  if (!sameNumbersAgree) {
    std::printf("FAIL: with the same numbers the global means differ by more than 1 %%\n");
    return 1;
  }
  if (!meansAgree) {
    std::printf("FAIL: the global means differ by more than the limit: the tracers disagree\n");
    return 1;
  }
  return 0;
}

}  // namespace pathway::bench
