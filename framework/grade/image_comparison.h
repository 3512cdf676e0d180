// Compares a rendered image with a reference the way the grader does (docs/grading.md):
//   1. hard checks, each with its own message: size, non-finite pixels, dropped non-finite
//      samples, negative pixels where the filter cannot make them;
//   2. a test per tile and channel: t = (m_image - m_reference) / sqrt(V + floor²), where V is the
//      variance of the difference of the tile means; with V from R reference replicates t follows
//      Student's t with R - 1 degrees of freedom (where the render's own variance estimate is
//      larger, it replaces the replicates' up to a cap, which only makes the test more cautious).
//      The smallest p over all tiles and channels is Šidák-corrected to the family-wise level;
//   3. omnibus tests per channel on the same statistics over blocks (8x8 pixels, larger than a
//      filter's reach, so nearly independent) mapped to N(0, 1): Σ z² ~ χ²(blocks), which catches
//      differences spread thinly over many blocks, and Σ z / sqrt(blocks) ~ N(0, 1), which
//      catches a small bias of one sign everywhere. Bonferroni over the six. A block's variance is
//      the render's own where that is larger (the jackknife over its sample batches,
//      grade/jackknife_render.h;
//      Welch's degrees of freedom), so a valid but noisier method passes: they judge the
//      expectation, not the noise;
//   4. with replicates, the lower tail: Σ (m_image - m_reference)² over the blocks against Σ of
//      the reference mean's own variance, which is what an image without any noise would show
//      (the reference is a mean of R renders, not the truth). Far below it, the image copies the
//      reference: the chance of an exact image coming that close (a weighted χ², Satterthwaite's
//      degrees of freedom) below tooCloseAlpha fails it. Honest renders, noisy, sit above 1.
// The image passes when no hard check fails, neither family-wise p is below its α, it is not
// too close, and, where the case requires a technique that lowers the noise, it is not far
// noisier than the reference's (both by the jackknife).
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "film/film.h"

namespace pathway {

// The test's settings, declared once.
struct ComparisonSettings {
  int tileSize = 8;            // pixels per tile side
  int omnibusBlockSize = 8;    // pixels per side of the blocks the omnibus tests add up
  double tileAlpha = 5e-4;     // family-wise false-alarm rate of the tile tests
  double omnibusAlpha = 5e-4;  // family-wise false-alarm rate of the six omnibus tests
  // Differences this small are never significant, even where the reference has no noise at all
  // (background, flat eye-light regions): float rounding between equivalent implementations.
  double relativeFloor = 1e-4;
  double absoluteFloor = 1e-6;
  // The render's own variance estimate may raise a tile's variance up to this many times the
  // replicates' (100 standard deviations): a rare sample the 64 replicates never drew (a firefly,
  // a hit on a sub-pixel sliver) can be that far out, measured over 1000 seeds; a bias spread over
  // many tiles is still caught by the omnibus tests.
  double ownVarianceCap = 1e4;
  // A block's own variance (the jackknife's) counts up to this many times the
  // replicates' (8 times the standard deviation): a valid method may be that much noisier; a
  // broken stage cannot excuse a bias by noise beyond it. Where the reference renders have no
  // noise at all (cosine-weighted directions under an open sky give every sample the same value)
  // the cap is relative to (noiselessFraction x the block's value)² instead.
  double ownNoiseCap = 64.0;
  double noiselessFraction = 0.01;
  // The omnibus tests clamp each block's z to ±this (P(|z| > 5) = 6e-7 for a correct stage).
  double omnibusClamp = 5.0;
  // An image fails as too close to the reference when even an exact image (no noise at all)
  // would come that close with less than this probability: only a copy of the reference does.
  double tooCloseAlpha = 1e-6;
};

struct ComparisonInput {
  const Image* image = nullptr;      // the submission's render
  const Image* reference = nullptr;  // the reference's mean
  // The variance of ONE render's tile mean (constant over each tile's pixels), from `replicates`
  // independent reference renders at the submission's spp. Without it (nullptr), the variances
  // come from the two images' per-pixel variance estimates, summed over the tile as if pixels
  // were independent (true for the box filter), and t is taken as normal.
  const Image* tileVariance = nullptr;
  const Image* blockVariance = nullptr;  // the same for the omnibus blocks (nullptr: use tiles)
  int replicates = 0;
  const Image* imageVariance = nullptr;  // per pixel: the render's own variance estimate
  // With replicates: the render's jackknife images (FilmImages::jackknife), for its own variance
  // of tile and block means (nullptr or fewer than two: the replicates' alone).
  const std::vector<Image>* jackknife = nullptr;
  const Image* referenceVariance = nullptr;  // per pixel, when tileVariance is absent
  // With replicates: one reference render's variance of a block's mean by the jackknife over as
  // many batches as the render's (constant over each block), so that the noise note compares
  // like with like (nullptr: no note). Low-discrepancy samples make both estimates too large.
  const Image* referenceJackknife = nullptr;
  double referenceTypicalNoise = 0.0;  // a reference render's typicalNoise (its record)
  // Where the stage requires a technique that lowers the noise but not the expectation (stage
  // 5's light sampling): the most times as noisy as the reference's a render may be (0: no
  // bound), and what a render past it left out, in words for the student.
  double noiseBound = 0.0;
  std::string requiredTechnique;
  // Var(Σ z) / blocks over the replicates: above 1 where a wide filter correlates neighbouring
  // blocks. The mean-shift test divides by it.
  glm::dvec3 blockCorrelation{1.0};
  // Without replicates: how much the filter inflates a tile's variance over the sum of its
  // pixels' (1 for the box filter, whose pixels are independent).
  double pixelCorrelation = 1.0;
  bool negativeValuesAllowed = false;  // the filter has negative lobes
  uint64_t droppedSamples = 0;         // non-finite samples the render dropped
};

// p-values above this print as "p > 0.99": the corrections cap them at 1, which reads as a
// certainty they are not.
constexpr double kLargestShownP = 0.99;

struct TileVerdict {
  int x0, y0, x1, y1;  // pixels [x0, x1) x [y0, y1)
  Color t{0.0f};       // per channel
  Color z{0.0f};       // t mapped to N(0, 1)
  double p = 1.0;      // smallest two-sided p of the three channels
  bool failed = false;
};

struct Comparison {
  std::vector<std::string> hardFailures;  // empty when the hard checks pass
  int width = 0, height = 0;
  size_t nonFinitePixels = 0, negativePixels = 0;
  int tileSize = 0;                // pixels per tile side
  std::vector<TileVerdict> tiles;  // row by row; empty when a hard check stopped the comparison
  double degreesOfFreedom = 0.0;   // of the tile statistics (infinity: normal)
  double tileThresholdP = 0.0;     // a tile fails below this p (Šidák over tiles x 3)
  double worstTileP = 1.0;         // family-wise p of the most extreme tile
  size_t failingTiles = 0;
  std::vector<TileVerdict> blocks;      // the omnibus tests' blocks, z only (clamped)
  double chiSquaredP[3] = {1, 1, 1};    // per channel, Σ z² ~ χ²(tiles)
  double meanShiftP[3] = {1, 1, 1};     // per channel, Σ z / sqrt(tiles) ~ N(0, 1)
  double omnibusP = 1.0;                // family-wise (Bonferroni over the six)
  double meanRelativeDifference = 0.0;  // (mean image - mean reference) / mean reference
  // The render's typicalNoise over a reference render's (both by the jackknife; 0: not
  // measured): a note for a student whose method is valid but noisier, a warning when it
  // reaches the cap, and a failure past the case's noiseBound.
  double noiseRatio = 0.0;
  double noiseBound = 0.0;        // from the input
  std::string requiredTechnique;  // from the input
  // Test 4: Σ d² / Σ Var(reference mean) over the blocks (about 1 for an exact image, more for a
  // render; < 0: not measured, without replicates or noise), and P(an exact image <= it).
  double closeness = -1.0;
  double closenessP = 1.0;

  bool tooClose(const ComparisonSettings& settings) const {
    return closenessP < settings.tooCloseAlpha;
  }
  // A required technique left out: far noisier than any valid method (ComparisonInput).
  bool tooNoisy() const { return noiseBound > 0.0 && noiseRatio > noiseBound; }
  // The expectation's tests: no hard failure, and neither family-wise p below its α.
  bool meanAgrees(const ComparisonSettings& settings) const {
    return hardFailures.empty() && worstTileP >= settings.tileAlpha &&
           omnibusP >= settings.omnibusAlpha;
  }
  bool passed(const ComparisonSettings& settings) const;
  // A few lines for a person: the hard failures, or the numbers of the statistical tests.
  std::string describe(const ComparisonSettings& settings) const;
};

// Throws nothing for bad images: every problem becomes a hard failure.
Comparison compareImages(const ComparisonInput& input, const ComparisonSettings& settings = {});

// Per tile and channel: the variance of one render's tile mean over `replicates` images
// (each the same size), constant over each tile's pixels. Used to make references.
Image replicateTileVariance(const std::vector<Image>& replicates, int tileSize);
// Per block and channel: one render's own variance of the block mean by the jackknife over its
// batch images (grade/jackknife_render.h), constant over each block's pixels.
Image jackknifeBlockVariance(const std::vector<Image>& jackknife, int blockSize);
// How noisy one render typically is against a reference: the median, over the blocks where
// `referenceJackknife` (a grading reference's jackknifeVariance) has noise, of the render's
// jackknife variance of the block mean (`ownJackknife`, from jackknifeBlockVariance) over the
// reference's, channels summed. A median, not a sum: rare huge samples (a small light found by a
// bounce, a firefly) would make a sum swing tenfold between renders of one stage. 0 without
// blocks that have noise.
double typicalNoise(const Image& ownJackknife, const Image& referenceJackknife, int blockSize);
// Var(Σ_blocks (m - mean) / sd) / blocks over the replicates, per channel (see blockCorrelation).
glm::dvec3 replicateBlockCorrelation(const std::vector<Image>& replicates, int blockSize);

// A tile: pixels [x0, x1) x [y0, y1).
struct TileBounds {
  int x0, y0, x1, y1;
  double pixels() const { return double(x1 - x0) * (y1 - y0); }
};
// The image cut into tiles of `tileSize` (smaller at the right and bottom borders), row by row.
std::vector<TileBounds> tilesOf(int width, int height, int tileSize);
glm::dvec3 tileMean(const Image& image, const TileBounds& tile);
// A width x height image constant over each tile of `tileSize`, at value(tile).
Image constantOverTiles(int width, int height, int tileSize,
                        const std::function<glm::dvec3(const TileBounds&)>& value);

// The smallest relative bias, the same everywhere (the image times 1 + b), that the whole-image
// mean-shift test catches in half of the renders of a stage as noisy as the reference's: from a
// grading reference's mean and one render's block variance. Per channel, the smallest of the
// three (any channel failing fails the case); infinity where the image is black.
double smallestDetectableBias(const Image& mean, const Image& blockVariance, int blockSize,
                              int replicates, const glm::dvec3& blockCorrelation,
                              const ComparisonSettings& settings = {});

// An upper bound on how much a filter of this radius (in pixels) inflates the variance of a sum
// of pixels over the sum of their variances: the number of pixels one sample reaches.
double filterPixelCorrelation(double filterRadius);

}  // namespace pathway
