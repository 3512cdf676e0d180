// Parts of a render over disjoint sample ranges merge into the render of their union, and
// `pathway merge` refuses parts that do not belong together.
#include "cluster/part_merge.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.h"
#include "engine/render_session.h"
#include "io/partial_film.h"
#include "run_command.h"
#include "stage_under_test.h"
#include "test_scenes.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// Summation order is all that differs between a merge and one render. Each sum here adds at most
// a few hundred terms, so the doubles differ by a few ulps of the sum of the terms' magnitudes;
// 1e-12 of that is thousands of times above it and still far below anything a float image shows.
constexpr double kSumTolerance = 1e-12;

class PartMerge : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder("pathway_merge");
    recipe_.integrator = test::stage(5);
    recipe_.settings.width = 40;  // over a tile edge, so the filter's reach crosses tiles
    recipe_.settings.height = 36;
    recipe_.settings.samplesPerPixel = 16;
    recipe_.settings.samplesPerPass = 16;  // one pass: the parts are summed in other passes
    recipe_.settings.filter = FilterType::MitchellNetravali;  // negative lobes, reach 2 pixels
    recipe_.settings.sampler = SamplerType::Stratified;       // strata sized from the whole spp
    recipe_.settings.seed = 5;
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Renders samples [begin, end) of the recipe and writes them as a part.
  std::string writePart(uint32_t begin, uint32_t end, uint64_t seed = 5) {
    RenderRecipe recipe = recipe_;
    recipe.settings.sampleBegin = begin;
    recipe.settings.sampleEnd = end;
    recipe.settings.samplesPerPass = 2;
    recipe.settings.seed = seed;
    const Camera camera(scene_, recipe.settings.width, recipe.settings.height);
    RenderSession session(tracer_, camera, recipe);
    session.renderer().renderAll();
    const RenderResult result = session.develop();
    const std::string path = (dir_ / ("part" + std::to_string(begin) + "-" + std::to_string(end) +
                                      "-" + std::to_string(seed) + ".exr"))
                                 .string();
    writePartialFilm(path, session.renderer().film(), result.images, result.metadata);
    return path;
  }

  const Scene scene_ = test::boxRoom();
  const RayTracer tracer_{scene_};
  RenderRecipe recipe_;
  fs::path dir_;
};

double relativeDifference(double a, double b, double scale) {
  return std::fabs(a - b) / std::max(scale, 1e-300);
}

TEST_F(PartMerge, PartsMergeIntoTheImageOfOneRender) {
  PATHWAY_REQUIRE_REFERENCE();
  const Camera camera(scene_, recipe_.settings.width, recipe_.settings.height);
  RenderSession whole(tracer_, camera, recipe_);
  whole.renderer().renderAll();
  const RenderResult expected = whole.develop();

  const std::vector<std::string> parts = {writePart(10, 16), writePart(0, 3), writePart(3, 10)};
  const MergedRender merged = mergeParts(parts, false);
  EXPECT_EQ(merged.metadata.sampleBegin, 0u);
  EXPECT_EQ(merged.metadata.sampleEnd, 16u);

  const Film& film = whole.renderer().film();
  double worstSum = 0.0, worstPixel = 0.0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const PixelSums& a = film.at(x, y);
      const PixelSums& b = merged.film.at(x, y);
      ASSERT_EQ(a.sampleCount, b.sampleCount) << x << "," << y;
      // Each sum against the magnitude of its terms: Σ|w| bounds |Σ w·L| / max L.
      for (int c = 0; c < 3; ++c) {
        worstSum = std::max(
            worstSum,
            relativeDifference(a.weightedRadiance[c], b.weightedRadiance[c],
                               a.absWeight * (1.0 + std::fabs(a.weightedRadiance[c] / a.weight))));
        worstSum = std::max(
            worstSum, relativeDifference(a.squaredWeightRadiance2[c], b.squaredWeightRadiance2[c],
                                         a.squaredWeightRadiance2[c]));
      }
      worstSum = std::max(worstSum, relativeDifference(a.weight, b.weight, a.absWeight));
      worstSum =
          std::max(worstSum, relativeDifference(a.squaredWeight, b.squaredWeight, a.squaredWeight));
      const size_t i = static_cast<size_t>(y) * film.width() + x;
      for (int c = 0; c < 3; ++c)
        worstPixel =
            std::max(worstPixel, relativeDifference(expected.images.color.pixels[i][c],
                                                    merged.images.color.pixels[i][c],
                                                    std::fabs(expected.images.color.pixels[i][c])));
    }
  EXPECT_LE(worstSum, kSumTolerance);
  // Developed to float, the images agree to a float's rounding (2^-23 relative is one ulp).
  EXPECT_LE(worstPixel, 2.0 / (1 << 23));
  std::printf("largest difference: film sums %.3g of their terms' magnitude, pixels %.3g\n",
              worstSum, worstPixel);

  // The counters add up to the whole render's.
  const RenderMetadata& metadata = merged.metadata;
  const RayCounters& c = whole.renderer().stats().counters;
  EXPECT_EQ(metadata.primaryRays, c.primary);
  EXPECT_EQ(metadata.secondaryRays, c.secondary);
  EXPECT_EQ(metadata.shadowRays, c.shadow);
  EXPECT_EQ(metadata.samples, c.samples);
  EXPECT_EQ(metadata.spp, 16u);
  EXPECT_EQ(metadata.sampleBegin, 0u);
  EXPECT_EQ(metadata.sampleEnd, 16u);

  // The order the parts are given in does not matter: they are added in the order of ranges.
  const MergedRender reordered = mergeParts({parts[1], parts[2], parts[0]}, false);
  EXPECT_EQ(reordered.images.color.pixels, merged.images.color.pixels);
  // A merge of merges is a merge.
  const std::string firstTwo = (dir_ / "first-two.exr").string();
  const MergedRender partial = mergeParts({parts[1], parts[2]}, true);
  writePartialFilm(firstTwo, partial.film, partial.images, partial.metadata);
  const MergedRender twice = mergeParts({firstTwo, parts[0]}, false);
  EXPECT_EQ(twice.images.color.pixels, merged.images.color.pixels);
}

// The message, when mergeParts refuses `paths`.
std::string refusal(const std::vector<std::string>& paths, bool allowIncomplete = false) {
  try {
    mergeParts(paths, allowIncomplete);
  } catch (const PathwayError& error) {
    return error.what();
  }
  return "(accepted)";
}

TEST_F(PartMerge, PartsThatDoNotBelongTogetherAreRefusedByName) {
  PATHWAY_REQUIRE_REFERENCE();
  const std::string a = writePart(0, 8), b = writePart(8, 16), overlapping = writePart(6, 12);
  const std::string otherSeed = writePart(8, 16, 9);
  EXPECT_NE(refusal({a, overlapping}).find("overlap"), std::string::npos);
  EXPECT_NE(refusal({a, otherSeed}).find("seed"), std::string::npos);
  EXPECT_NE(refusal({a}).find("samples 8:16 are missing"), std::string::npos);
  EXPECT_EQ(refusal({a}, true), "(accepted)");
  const std::string late = writePart(12, 16);
  EXPECT_NE(refusal({a, late}).find("samples 8:12 are missing"), std::string::npos);
  EXPECT_NE(refusal({a, late}, true).find("samples 8:12 are missing"), std::string::npos);

  // A truncated part, a missing file, and a render that is not a part.
  const std::string truncated = (dir_ / "truncated.exr").string();
  {
    std::ifstream in(b, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(truncated, std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  EXPECT_NE(refusal({a, truncated}).find(truncated), std::string::npos);
  const std::string missing = (dir_ / "missing.exr").string();
  EXPECT_NE(refusal({a, missing}).find(missing), std::string::npos);
  const std::string plain = (dir_ / "plain.exr").string();
  const RenderResult render = runRender(tracer_, recipe_);
  writeExr(plain, render.images, render.metadata);
  EXPECT_NE(refusal({plain}).find("not a part"), std::string::npos);
  // Another image size.
  RenderRecipe wider = recipe_;
  recipe_.settings.width = 41;
  const std::string otherSize = writePart(8, 16);
  recipe_ = wider;
  EXPECT_NE(refusal({a, otherSize}).find("pixels"), std::string::npos);
}

TEST(PartMergeCli, MergeRefusesAndWritesNothing) {
  PATHWAY_REQUIRE_REFERENCE();
  const fs::path dir = test::freshTestFolder("pathway_merge_cli");
  const std::string pathway = PATHWAY_BINARY;
  const std::string scene = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";
  const std::string render =
      pathway + " render " + scene + " -q -i " + test::stage(5) + " --width 24 --spp 8 --samples ";
  ASSERT_EQ(test::runCommand(render + "0:4 -o " + (dir / "a.exr").string()).exitCode, 0);
  ASSERT_EQ(test::runCommand(render + "2:8 -o " + (dir / "b.exr").string()).exitCode, 0);
  const test::CommandOutcome refused =
      test::runCommand(pathway + " merge " + (dir / "a.exr").string() + " " +
                       (dir / "b.exr").string() + " -o " + (dir / "out.exr").string());
  EXPECT_EQ(refused.exitCode, 1);
  EXPECT_NE(refused.output.find("overlap"), std::string::npos) << refused.output;
  EXPECT_FALSE(fs::exists(dir / "out.exr"));
  // A range outside the render's samples is refused before it renders.
  const test::CommandOutcome outside =
      test::runCommand(render + "4:9 -o " + (dir / "c.exr").string());
  EXPECT_EQ(outside.exitCode, 1);
  EXPECT_NE(outside.output.find("4:9"), std::string::npos) << outside.output;
  EXPECT_FALSE(fs::exists(dir / "c.exr"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace pathway
