// `pathway warptest`: a stage's sampling routine against the density it claims, by χ² tests, for
// the student's stage, the reference's, or a stage library's. Stage 2: the hemisphere directions
// against their pdf (grade/warp_fit.h), with a picture (grade/warp_picture.h). Stage 5: the points
// on the emitters against their pdfArea (grade/light_sampling_fit.h), for both ways of picking an
// emitter. Over many seeds: how often a correct routine fails.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/grade_options.h"
#include "core/error.h"
#include "core/variant.h"
#include "grade/stage_warp_test.h"
#include "grade/warp_picture.h"
#include "scene/gltf_loader.h"
#include "stage_loading/stage_library.h"
#include "stage_loading/student_stages.h"

namespace pathway {
namespace {

struct WarptestOptions {
  int stage = 2;
  std::string variant = "student";
  std::vector<std::string> stageLibraries;
  int samples = kWarpTestSamples;
  uint64_t seed = 1;
  int seeds = 1;
  std::string picture;
  std::string scene = kScenesDir + "/" + kWarpTestScene;
};

int run(const WarptestOptions& options) {
  const Variant variant = options.variant == "reference" ? Variant::Reference : Variant::Student;
  if (options.stage == 5 && !options.picture.empty())
    throw PathwayError(
        "warptest --picture draws stage 2's directions; stage 5's test prints its "
        "verdict only");
  // The student's stages as this build made them, or the libraries given (in this process,
  // unsandboxed, as `grade --calibrate` loads them: a tool for one's own code).
  for (const std::string& library : options.stageLibraries) loadStageLibrary(library);
  if (variant == Variant::Student && options.stageLibraries.empty()) loadStudentStages();
  const std::string whose =
      options.stageLibraries.empty() ? variantName(variant) : options.stageLibraries.front();
  const std::string what =
      options.stage == 2
          ? "stage 2 (" + whose + "): sampleCosineHemisphere against cosineHemispherePdf, " +
                std::to_string(options.samples) + " directions"
          : "stage 5 (" + whose + "): sampleLight's points against their pdfArea on " +
                options.scene + ", " + std::to_string(options.samples) + " points";
  const Scene lights = options.stage == 5 ? loadScene(options.scene) : Scene{};
  const auto test = [&](uint64_t seed) {
    return runStageWarpTest(options.stage, variant, &lights, options.samples, seed,
                            !options.picture.empty());
  };

  if (options.seeds == 1) {
    const std::string title = what + ", seed " + std::to_string(options.seed);
    const StageWarpTest outcome = test(options.seed);
    std::printf("%s\n%s\n", title.c_str(), outcome.verdict.c_str());
    if (!options.picture.empty()) {
      writeWarpTestSvg(options.picture, outcome.hemisphere, title);
      std::printf("picture: %s\n", options.picture.c_str());
    }
    return outcome.passed ? 0 : 1;
  }
  // Many seeds: a correct routine fails about once in 10000, a wrong one every time.
  int failures = 0;
  double smallestP = 1.0;
  uint64_t smallestAt = options.seed;
  for (int k = 0; k < options.seeds; ++k) {
    const uint64_t seed = options.seed + static_cast<uint64_t>(k);
    const StageWarpTest outcome = test(seed);
    if (!outcome.passed) {
      ++failures;
      std::printf("seed %llu: %s\n", static_cast<unsigned long long>(seed),
                  outcome.verdict.c_str());
    }
    if (outcome.p < smallestP) smallestP = outcome.p, smallestAt = seed;
  }
  std::printf("%s, seeds %llu to %llu: %d of %d failed (rate %.4f), smallest p %.3g at seed %llu\n",
              what.c_str(), static_cast<unsigned long long>(options.seed),
              static_cast<unsigned long long>(options.seed + options.seeds - 1), failures,
              options.seeds, double(failures) / options.seeds, smallestP,
              static_cast<unsigned long long>(smallestAt));
  return failures == 0 ? 0 : 1;
}

}  // namespace

Command addWarptestCommand(CLI::App& app) {
  auto options = std::make_shared<WarptestOptions>();
  CLI::App* warptest = app.add_subcommand(
      "warptest", "Test a stage's sampling routine against its density (chi-squared tests)");
  warptest->footer(
      "Examples:\n"
      "  pathway warptest --picture warp.svg   your stage 2's hemisphere directions, and a "
      "picture\n"
      "  pathway warptest --stage 5            your stage 5's points on the emitters\n"
      "  pathway warptest --variant reference --samples 1000000 --seed 7\n"
      "  pathway warptest --variant reference --seeds 1000   how often a right routine fails\n"
      "Exit status 0 when the samples fit the density (at every seed), 1 when they do not.");
  warptest
      ->add_option("--stage", options->stage,
                   "Whose routine: stage 2 (hemisphere directions) "
                   "or 5 (points on the emitters)")
      ->check(CLI::IsMember({2, 5}))
      ->capture_default_str();
  warptest->add_option("--variant", options->variant, "Whose stage: student or reference")
      ->check(CLI::IsMember({"student", "reference"}))
      ->capture_default_str();
  warptest->add_option("--stages-library", options->stageLibraries,
                       "Test the stage of this library instead (student stage files compiled on "
                       "their own, as the grader and the mutant suite build them)");
  warptest->add_option("--samples", options->samples, "Samples to draw")
      ->check(CLI::Range(1000, 100000000))
      ->capture_default_str();
  warptest->add_option("--seed", options->seed, "Seed of the numbers drawn")->capture_default_str();
  auto* seeds = warptest
                    ->add_option("--seeds", options->seeds,
                                 "Test this many seeds from --seed on and count the failures")
                    ->check(CLI::Range(1, 1000000))
                    ->capture_default_str();
  warptest
      ->add_option("--picture", options->picture,
                   "Stage 2: write the directions, both histograms and their difference as an SVG")
      ->excludes(seeds);
  warptest->add_option("--scene", options->scene, "Stage 5: the scene whose emitters are sampled")
      ->check(CLI::ExistingFile)
      ->capture_default_str();
  return {warptest, [options] { return run(*options); }};
}

}  // namespace pathway
