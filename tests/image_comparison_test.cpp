// The grader's image comparison on images with known statistics: it passes what is the same up to
// the stated noise, fails a bias in one tile or a small one spread everywhere, and turns bad
// images into hard failures with their own messages.
#include "grade/image_comparison.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "grade/statistics.h"
#include "sampling/pcg32.h"

namespace pathway {
namespace {

constexpr int kSize = 64;  // 8 x 8 tiles of 8 x 8 pixels
constexpr int kReplicates = 64;
constexpr double kPixelSigma = 0.05;  // noise of one pixel of one render

// A noisy render of a smooth image: value + N(0, sigma²) per pixel and channel.
Image noisyRender(uint64_t seed, double bias = 0.0) {
  Pcg32 rng(seed);
  Image image(kSize, kSize);
  for (int y = 0; y < kSize; ++y) {
    for (int x = 0; x < kSize; ++x) {
      for (int c = 0; c < 3; ++c) {
        // Box-Muller from two uniforms.
        const double u1 = 1.0 - rng.nextFloat(), u2 = rng.nextFloat();
        const double normal = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
        image.at(x, y)[c] = static_cast<float>(0.5 + 0.3 * x / kSize + bias + kPixelSigma * normal);
      }
    }
  }
  return image;
}

struct Reference {
  Image mean, tileVariance;
};

Reference makeReference() {
  std::vector<Image> replicates;
  for (int i = 0; i < kReplicates; ++i) replicates.push_back(noisyRender(1000 + i));
  Reference reference{Image(kSize, kSize), replicateTileVariance(replicates, 8)};
  for (size_t p = 0; p < reference.mean.pixels.size(); ++p) {
    glm::dvec3 sum(0.0);
    for (const Image& r : replicates) sum += glm::dvec3(r.pixels[p]);
    reference.mean.pixels[p] = Color(sum / double(kReplicates));
  }
  return reference;
}

Comparison compare(const Image& image, const Reference& reference) {
  ComparisonInput input;
  input.image = &image;
  input.reference = &reference.mean;
  input.tileVariance = &reference.tileVariance;
  input.replicates = kReplicates;
  return compareImages(input);
}

TEST(ImageComparison, ReplicateTileVarianceMatchesTheNoiseModel) {
  const Reference reference = makeReference();
  // A tile mean of 64 independent pixels has variance sigma² / 64; estimated from 64 replicates,
  // it is within 4.5 standard errors of that (relative SE of a variance: sqrt(2 / 63)).
  const double expected = kPixelSigma * kPixelSigma / 64.0;
  const double measured = reference.tileVariance.at(3, 3).y;
  EXPECT_NEAR(measured, expected, 4.5 * std::sqrt(2.0 / 63.0) * expected);
}

TEST(ImageComparison, FreshRendersOfTheSameImagePass) {
  const Reference reference = makeReference();
  const ComparisonSettings settings;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const Comparison result = compare(noisyRender(seed), reference);
    EXPECT_TRUE(result.passed(settings)) << "seed " << seed << "\n" << result.describe(settings);
    EXPECT_EQ(result.tiles.size(), 64u);
    EXPECT_EQ(result.degreesOfFreedom, kReplicates - 1.0);
  }
}

TEST(ImageComparison, OneBiasedTileFailsAndIsNamed) {
  const Reference reference = makeReference();
  Image image = noisyRender(7);
  // A tile 0.05 brighter: 8 standard deviations of its mean (sigma / 8 = 0.00625).
  for (int y = 16; y < 24; ++y)
    for (int x = 40; x < 48; ++x) image.at(x, y) += Color(0.05f, 0.0f, 0.0f);
  const ComparisonSettings settings;
  const Comparison result = compare(image, reference);
  EXPECT_FALSE(result.passed(settings));
  EXPECT_EQ(result.failingTiles, 1u);
  const TileVerdict& tile = result.tiles[2 * 8 + 5];
  EXPECT_TRUE(tile.failed);
  EXPECT_GT(tile.t.x, 5.0f);
  EXPECT_LT(result.worstTileP, settings.tileAlpha);
}

TEST(ImageComparison, ASmallBiasEverywhereFailsTheOmnibusTest) {
  const Reference reference = makeReference();
  // 0.005 everywhere: 0.8 of a tile's standard deviation, far below what fails a single tile;
  // over 64 tiles the mean of z shifts by 0.8 * sqrt(64) = 6.4 standard errors.
  const ComparisonSettings settings;
  const Comparison result = compare(noisyRender(8, 0.005), reference);
  EXPECT_EQ(result.failingTiles, 0u);
  EXPECT_LT(result.omnibusP, settings.omnibusAlpha) << result.describe(settings);
  EXPECT_FALSE(result.passed(settings));
  // Said in words, not as "no tile differs" beside a failure; each block's z is kept for its map.
  EXPECT_NE(result.describe(settings).find("small and spread over the whole image"),
            std::string::npos)
      << result.describe(settings);
  ASSERT_EQ(result.blocks.size(), 64u);
  double meanZ = 0.0;
  for (const TileVerdict& block : result.blocks) meanZ += block.z.x / 64.0;
  EXPECT_GT(meanZ, 0.4);  // 0.8 expected
}

TEST(ImageComparison, CappedPValuesReadAsAboveNinetyNine) {
  const Reference reference = makeReference();
  const ComparisonSettings settings;
  int capped = 0;  // Bonferroni over six tests caps p at 1 about half the time
  for (uint64_t seed = 9; seed < 40; ++seed) {
    const Comparison result = compare(noisyRender(seed), reference);
    const std::string text = result.describe(settings);
    EXPECT_EQ(text.find("p = 1 "), std::string::npos) << text;
    if (result.omnibusP <= 0.99) continue;
    ++capped;
    EXPECT_NE(text.find("omnibus p > 0.99"), std::string::npos) << text;
  }
  EXPECT_GT(capped, 0);
}

TEST(ImageComparison, BadImagesAreHardFailuresWithTheirOwnMessages) {
  const Reference reference = makeReference();
  const ComparisonSettings settings;

  const Image small(32, 32);
  Comparison result = compare(small, reference);
  ASSERT_EQ(result.hardFailures.size(), 1u);
  EXPECT_NE(result.hardFailures[0].find("32x32"), std::string::npos);

  Image nan = noisyRender(9);
  nan.at(5, 5).x = NAN;
  nan.at(6, 5).y = INFINITY;
  result = compare(nan, reference);
  EXPECT_FALSE(result.passed(settings));
  EXPECT_EQ(result.nonFinitePixels, 2u);
  EXPECT_NE(result.describe(settings).find("2 pixels are NaN or infinite"), std::string::npos);

  Image negative = noisyRender(10);
  negative.at(1, 1) = Color(-0.1f);
  result = compare(negative, reference);
  EXPECT_NE(result.describe(settings).find("negative"), std::string::npos);
  ComparisonInput allowed;
  allowed.image = &negative;
  allowed.reference = &reference.mean;
  allowed.tileVariance = &reference.tileVariance;
  allowed.replicates = kReplicates;
  allowed.negativeValuesAllowed = true;  // Mitchell-Netravali can make negative pixels
  EXPECT_TRUE(compareImages(allowed).hardFailures.empty());

  allowed.droppedSamples = 3;
  EXPECT_NE(compareImages(allowed).describe(settings).find("3 radiance samples"),
            std::string::npos);
}

TEST(ImageComparison, NoiseFreeRegionsTolerateRoundingButNotErrors) {
  // A constant reference with zero variance (a background): float rounding passes, 1% fails.
  Image reference(16, 16), tileVariance(16, 16);
  for (Color& c : reference.pixels) c = Color(0.3f);
  Image rounded = reference, wrong = reference;
  for (Color& c : rounded.pixels) c = Color(std::nextafter(0.3f, 1.0f));
  for (Color& c : wrong.pixels) c = Color(0.303f);
  ComparisonInput input;
  input.reference = &reference;
  input.tileVariance = &tileVariance;
  input.replicates = kReplicates;
  const ComparisonSettings settings;
  input.image = &rounded;
  EXPECT_TRUE(compareImages(input).passed(settings));
  input.image = &wrong;
  EXPECT_FALSE(compareImages(input).passed(settings));
}

TEST(ImageComparison, TheRendersOwnVarianceExcusesAFireflyButNotABiasEverywhere) {
  const Reference reference = makeReference();
  const ComparisonSettings settings;
  // A firefly: one pixel 5 (its tile mean +0.07, 11 standard deviations), with the render's own
  // variance estimate raised accordingly (5² for that pixel: 5² / 64² for the tile mean).
  Image firefly = noisyRender(11);
  firefly.at(20, 20) = Color(5.0f);
  Image ownVariance(kSize, kSize);
  for (Color& c : ownVariance.pixels) c = Color(float(kPixelSigma * kPixelSigma));
  ownVariance.at(20, 20) = Color(5.0f * 5.0f);
  ComparisonInput input;
  input.image = &firefly;
  input.reference = &reference.mean;
  input.tileVariance = &reference.tileVariance;
  input.replicates = kReplicates;
  EXPECT_FALSE(compareImages(input).passed(settings));  // without its own variance: an outlier
  input.imageVariance = &ownVariance;
  EXPECT_TRUE(compareImages(input).passed(settings));
  // An image far too bright everywhere cannot hide behind an enormous own variance: the cap
  // (100 standard deviations) leaves each tile at t = 1.6, and the omnibus test adds them up.
  const Image bright = noisyRender(12, 1.0);
  for (Color& c : ownVariance.pixels) c = Color(1e6f);
  input.image = &bright;
  const Comparison hidden = compareImages(input);
  EXPECT_EQ(hidden.failingTiles, 0u);
  EXPECT_LT(hidden.omnibusP, settings.omnibusAlpha);
  EXPECT_FALSE(hidden.passed(settings));
}

// A render in 8 sample batches, `noise` times the reference's standard deviation, `bias` off:
// the whole image (the batches' mean) and its jackknife (the mean of the other 7, each in turn).
struct BatchedRender {
  Image image;
  std::vector<Image> jackknife;
};
BatchedRender batchedRender(uint64_t seed, double noise, double bias) {
  constexpr int kBatches = 8;
  std::vector<Image> batches;
  for (int b = 0; b < kBatches; ++b) {
    // Each batch has kBatches times the whole render's variance.
    Image batch = noisyRender(seed * 100 + b);
    for (int y = 0; y < kSize; ++y)
      for (int x = 0; x < kSize; ++x) {
        const double clean = 0.5 + 0.3 * x / kSize;
        const glm::dvec3 deviation = glm::dvec3(batch.at(x, y)) - clean;
        batch.at(x, y) = Color(clean + bias + noise * std::sqrt(double(kBatches)) * deviation);
      }
    batches.push_back(batch);
  }
  BatchedRender render{Image(kSize, kSize), {}};
  for (size_t p = 0; p < render.image.pixels.size(); ++p) {
    glm::dvec3 sum(0.0);
    for (const Image& batch : batches) sum += glm::dvec3(batch.pixels[p]);
    render.image.pixels[p] = Color(sum / double(kBatches));
  }
  for (const Image& left : batches) {
    Image without(kSize, kSize);
    for (size_t p = 0; p < without.pixels.size(); ++p)
      without.pixels[p] = Color(
          (glm::dvec3(render.image.pixels[p]) * double(kBatches) - glm::dvec3(left.pixels[p])) /
          double(kBatches - 1));
    render.jackknife.push_back(without);
  }
  return render;
}

// What a grading reference holds for the noise note (grading_reference.h): one reference render's
// jackknife variance of a block mean, and its typical noise, the median over 15 renders like it.
struct ReferenceNoise {
  Image jackknife;
  double typical = 0.0;
};
ReferenceNoise referenceNoise(const Reference& reference) {
  // The batches are independent: a render's jackknife estimates the replicates' variance.
  ReferenceNoise noise{reference.tileVariance};
  std::vector<double> typical;
  for (uint64_t seed = 500; seed < 515; ++seed)
    typical.push_back(typicalNoise(
        jackknifeBlockVariance(batchedRender(seed, 1.0, 0.0).jackknife, 8), noise.jackknife, 8));
  std::nth_element(typical.begin(), typical.begin() + 7, typical.end());
  noise.typical = typical[7];
  return noise;
}

ComparisonInput batchedInput(const Reference& reference, const ReferenceNoise& noise) {
  ComparisonInput input;
  input.reference = &reference.mean;
  input.tileVariance = &reference.tileVariance;
  input.replicates = kReplicates;
  input.negativeValuesAllowed = true;  // Gaussian noise this wide dips below 0
  input.referenceJackknife = &noise.jackknife;
  input.referenceTypicalNoise = noise.typical;
  return input;
}

TEST(ImageComparison, ANoisierValidRenderPassesByItsOwnVarianceAndABiasStillFails) {
  const Reference reference = makeReference();
  const ReferenceNoise noise = referenceNoise(reference);
  const ComparisonSettings settings;
  ComparisonInput input = batchedInput(reference, noise);
  // Three times the reference's standard deviation (9 times its variance), unbiased: judged by
  // the reference's noise alone it fails every time; by its own (the jackknife) it passes. Each
  // of the 20 seeds fails by chance with probability about 1e-3 (the two family-wise levels), so
  // all 20 pass but for about 2 % of runs; the seeds are fixed.
  int passedWithout = 0;
  for (uint64_t seed = 1; seed <= 20; ++seed) {
    const BatchedRender render = batchedRender(seed, 3.0, 0.0);
    input.image = &render.image;
    input.jackknife = nullptr;
    passedWithout += compareImages(input, settings).passed(settings);
    input.jackknife = &render.jackknife;
    const Comparison judged = compareImages(input, settings);
    EXPECT_TRUE(judged.passed(settings)) << "seed " << seed << "\n" << judged.describe(settings);
    // Its typical noise over a reference render's: 9 expected, the medians' spread around it.
    EXPECT_NEAR(judged.noiseRatio, 9.0, 3.0);
    EXPECT_NE(judged.describe(settings).find("times as noisy as the reference's"),
              std::string::npos);
  }
  EXPECT_EQ(passedWithout, 0);
  // The same noise with a bias of 0.02 everywhere (about one standard deviation of a tile mean
  // of this render, 8.5 over the image's 64 tiles) fails the whole-image test.
  const BatchedRender biased = batchedRender(21, 3.0, 0.02);
  input.image = &biased.image;
  input.jackknife = &biased.jackknife;
  EXPECT_FALSE(compareImages(input, settings).passed(settings));
  // A render 100 times as noisy (variance 10⁴ times) cannot hide a bias of 0.1 behind it: its own
  // variance counts up to ownNoiseCap (64) times the replicates', a tile standard deviation of
  // 0.05, so each tile is at z = 2 and the mean shift at 16 standard errors.
  const BatchedRender hidden = batchedRender(22, 100.0, 0.1);
  input.image = &hidden.image;
  input.jackknife = &hidden.jackknife;
  const Comparison capped = compareImages(input, settings);
  EXPECT_LT(capped.omnibusP, settings.omnibusAlpha) << capped.describe(settings);
  EXPECT_NE(capped.describe(settings).find("allow for no more than 64 times"), std::string::npos)
      << capped.describe(settings);
}

TEST(ImageComparison, TheNoiseNoteComparesLikeWithLike) {
  const Reference reference = makeReference();
  const ReferenceNoise noise = referenceNoise(reference);
  const ComparisonSettings settings;
  ComparisonInput input = batchedInput(reference, noise);
  // Renders made as the reference's are read as about as noisy (1), with no note; twice and
  // four times the standard deviation read about 4 and 16.
  for (const auto& [deviation, expected] : {std::pair{1.0, 1.0}, {2.0, 4.0}, {4.0, 16.0}}) {
    for (uint64_t seed = 30; seed < 36; ++seed) {
      const BatchedRender render = batchedRender(seed, deviation, 0.0);
      input.image = &render.image;
      input.jackknife = &render.jackknife;
      const Comparison judged = compareImages(input, settings);
      EXPECT_GT(judged.noiseRatio, expected / 1.6) << deviation << ", seed " << seed;
      EXPECT_LT(judged.noiseRatio, expected * 1.6) << deviation << ", seed " << seed;
      EXPECT_EQ(judged.describe(settings).find("times as noisy") == std::string::npos,
                deviation == 1.0)
          << judged.describe(settings);
    }
  }
  // Without the reference's own jackknife (a reference made before it) there is no note: the
  // replicates' spread is not estimated the way the render's is.
  const BatchedRender render = batchedRender(40, 4.0, 0.0);
  input.image = &render.image;
  input.jackknife = &render.jackknife;
  input.referenceJackknife = nullptr;
  EXPECT_EQ(compareImages(input, settings).noiseRatio, 0.0);
}

TEST(ImageComparison, ARenderPastTheCasesNoiseBoundFailsNamingTheTechnique) {
  const Reference reference = makeReference();
  const ReferenceNoise noise = referenceNoise(reference);
  const ComparisonSettings settings;
  ComparisonInput input = batchedInput(reference, noise);
  input.requiredTechnique = "the stage samples the light (README.md, Required)";
  // Unbiased and 16 times as noisy: within a bound of 40 it passes with a note; past a bound
  // of 8 it fails, saying how much noisier and what it left out.
  const BatchedRender render = batchedRender(50, 4.0, 0.0);
  input.image = &render.image;
  input.jackknife = &render.jackknife;
  input.noiseBound = 40.0;
  const Comparison within = compareImages(input, settings);
  EXPECT_FALSE(within.tooNoisy());
  EXPECT_TRUE(within.passed(settings)) << within.describe(settings);
  input.noiseBound = 8.0;
  const Comparison past = compareImages(input, settings);
  EXPECT_TRUE(past.tooNoisy());
  EXPECT_FALSE(past.passed(settings));
  const std::string text = past.describe(settings);
  EXPECT_NE(text.find("this case allows at most 8 times: the stage samples the light"),
            std::string::npos)
      << text;
  // Without a bound the same render passes.
  input.noiseBound = 0.0;
  EXPECT_TRUE(compareImages(input, settings).passed(settings));
}

TEST(ImageComparison, TheSmallestDetectableBiasIsCaughtAboutHalfTheTime) {
  const Reference reference = makeReference();
  const ComparisonSettings settings;
  const glm::dvec3 correlation(1.0);
  const double bias = smallestDetectableBias(reference.mean, reference.tileVariance, 8, kReplicates,
                                             correlation, settings);
  // The formula by hand on the first channel: z* sqrt(n) / Σ m / s over the 64 tiles.
  const double threshold = -normalQuantile(settings.omnibusAlpha / 12.0);
  double sum = 0.0;
  for (const TileBounds& t : tilesOf(kSize, kSize, 8)) {
    const double m = tileMean(reference.mean, t).x;
    const double floor = settings.relativeFloor * m + settings.absoluteFloor;
    sum += m / std::sqrt(reference.tileVariance.at(t.x0, t.y0).x * (1.0 + 1.0 / kReplicates) +
                         floor * floor);
  }
  EXPECT_NEAR(bias, threshold * 8.0 / sum, 0.05 * bias);  // the smallest channel's, within 5 %
  // Renders that much too bright fail the whole-image test in at least half of 100 seeds (any of
  // three channels may: about 7 in 8 expected), renders half as biased rarely (about 7 in 100);
  // bounds chosen at over 4 standard errors from those rates.
  const auto failures = [&](double b) {
    int failed = 0;
    for (uint64_t seed = 1; seed <= 100; ++seed) {
      Image image = noisyRender(500 + seed);
      for (Color& c : image.pixels) c *= float(1.0 + b);
      failed += compare(image, reference).omnibusP < settings.omnibusAlpha;
    }
    return failed;
  };
  EXPECT_GE(failures(bias), 50);
  EXPECT_LE(failures(0.5 * bias), 20);
}

}  // namespace
}  // namespace pathway
