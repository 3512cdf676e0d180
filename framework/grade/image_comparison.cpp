#include "grade/image_comparison.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "grade/statistics.h"

namespace pathway {

std::vector<TileBounds> tilesOf(int width, int height, int tileSize) {
  std::vector<TileBounds> tiles;
  for (int y = 0; y < height; y += tileSize)
    for (int x = 0; x < width; x += tileSize)
      tiles.push_back({x, y, std::min(width, x + tileSize), std::min(height, y + tileSize)});
  return tiles;
}

Image constantOverTiles(int width, int height, int tileSize,
                        const std::function<glm::dvec3(const TileBounds&)>& value) {
  Image result(width, height);
  for (const TileBounds& t : tilesOf(width, height, tileSize)) {
    const Color constant(value(t));
    for (int y = t.y0; y < t.y1; ++y)
      for (int x = t.x0; x < t.x1; ++x) result.at(x, y) = constant;
  }
  return result;
}

glm::dvec3 tileMean(const Image& image, const TileBounds& t) {
  glm::dvec3 sum(0.0);
  for (int y = t.y0; y < t.y1; ++y)
    for (int x = t.x0; x < t.x1; ++x) sum += glm::dvec3(image.at(x, y));
  return sum / t.pixels();
}

namespace {

// Σ var / n²: the variance of the tile mean when the pixels are independent.
glm::dvec3 independentTileVariance(const Image& variance, const TileBounds& t) {
  return tileMean(variance, t) / t.pixels();
}

double mean(const Image& image) {
  double sum = 0.0;
  for (const Color& c : image.pixels) sum += (double(c.x) + c.y + c.z) / 3.0;
  return image.pixels.empty() ? 0.0 : sum / image.pixels.size();
}

// A render noted as noisier: from twice the reference's (the ratio of two estimates of the same
// noise spreads about 1 by chance, most on cases with few noisy blocks).
constexpr double kNotedNoiseRatio = 2.0;

std::string formatNumber(double value) {
  std::ostringstream out;
  out.precision(3);
  out << value;
  return out.str();
}

// "p = 0.0123"; p-values capped at 1 (Bonferroni, Šidák) read "p > 0.99".
std::string formatP(double p) {
  return p > kLargestShownP ? "p > " + formatNumber(kLargestShownP) : "p = " + formatNumber(p);
}

// The test statistic of one tile (or omnibus block), per channel.
struct Unit {
  glm::dvec3 t, z, p;
};

// The render's own variance of the mean over `b`, from its jackknife images (one per left-out
// batch, grade/jackknife_render.h): (B - 1)/B Σ_j (m_j - their average)².
glm::dvec3 jackknifeVariance(const std::vector<Image>& jackknife, const TileBounds& b) {
  std::vector<glm::dvec3> means;
  glm::dvec3 sum(0.0);
  for (const Image& image : jackknife) sum += means.emplace_back(tileMean(image, b));
  const double count = static_cast<double>(jackknife.size());
  const glm::dvec3 average = sum / count;
  glm::dvec3 squares(0.0);
  for (const glm::dvec3& m : means) squares += (m - average) * (m - average);
  return squares * (count - 1.0) / count;
}

// The render's own noise at one tile or block, from its jackknife images (none: degrees 0).
struct OwnVariance {
  glm::dvec3 variance{0.0};  // of this unit's mean
  double degreesOfFreedom = 0.0;
  // Σ own / Σ replicates' over the unit and its 8 neighbours (where the replicates have noise;
  // 0: nowhere), with its degrees of freedom: a stable estimate of how much noisier the render
  // is here. The unit's own estimate alone (B - 1 degrees) is now and then far too small, by
  // chance, and a render 9 times as noisy judged by the replicates' variance there fails.
  glm::dvec3 neighbourhoodRatio{0.0};
  glm::dvec3 neighbourhoodDegrees{0.0};
};

// Per unit (`units` row by row, `perRow` of them in a row): the render's own noise.
std::vector<OwnVariance> ownVariances(const ComparisonInput& input,
                                      const std::vector<TileBounds>& units, size_t perRow,
                                      const Image& replicateVariance) {
  std::vector<OwnVariance> own(units.size());
  if (!input.jackknife || input.jackknife->size() < 2) return own;
  const double batchDegrees = input.jackknife->size() - 1.0;
  for (size_t i = 0; i < units.size(); ++i) {
    const TileBounds& b = units[i];
    own[i].variance = jackknifeVariance(*input.jackknife, b);
    own[i].degreesOfFreedom = batchDegrees;
  }
  const long columns = static_cast<long>(perRow);
  const long rows = static_cast<long>(units.size()) / columns;
  for (long row = 0; row < rows; ++row)
    for (long column = 0; column < columns; ++column) {
      glm::dvec3 mine(0.0), theirs(0.0), counted(0.0);
      for (long r = std::max(0L, row - 1); r <= std::min(rows - 1, row + 1); ++r)
        for (long c = std::max(0L, column - 1); c <= std::min(columns - 1, column + 1); ++c) {
          const TileBounds& b = units[r * columns + c];
          const glm::dvec3 replicates(replicateVariance.at(b.x0, b.y0));
          for (int channel = 0; channel < 3; ++channel)
            if (replicates[channel] > 0.0) {
              mine[channel] += own[r * columns + c].variance[channel];
              theirs[channel] += replicates[channel];
              counted[channel] += 1.0;
            }
        }
      OwnVariance& unit = own[row * columns + column];
      for (int channel = 0; channel < 3; ++channel)
        if (theirs[channel] > 0.0) {
          unit.neighbourhoodRatio[channel] = mine[channel] / theirs[channel];
          unit.neighbourhoodDegrees[channel] = batchDegrees * counted[channel];
        }
    }
  return own;
}

// The variance of the difference of the means over `b`: the replicates', widened by the render's
// own where that is larger. `ownPixels` (the tiles): the render's per-pixel estimate, up to
// ownVarianceCap, with the replicates' degrees of freedom. `ownBlock` (tiles and blocks): the
// jackknife's estimate, up to ownNoiseCap, with Welch's degrees of freedom.
Unit unitStatistic(const ComparisonInput& input, const ComparisonSettings& settings,
                   double degreesOfFreedom, const TileBounds& b, const Image* replicateVariance,
                   bool ownPixels, const OwnVariance& ownBlock) {
  const glm::dvec3 referenceMean = tileMean(*input.reference, b);
  const glm::dvec3 difference = tileMean(*input.image, b) - referenceMean;
  // Differences this small never count, even where the reference has no noise at all.
  const glm::dvec3 floor =
      settings.relativeFloor * glm::abs(referenceMean) + settings.absoluteFloor;
  glm::dvec3 variance(0.0), degrees(degreesOfFreedom);
  if (replicateVariance) {
    // The submission is one more render like the R replicates; the reference mean is their
    // average: Var(m_image - m_reference) = V (1 + 1/R). Where the render's own estimate is
    // larger, it is used instead, up to a cap: a rare sample that the replicates happened to
    // miss (a firefly; one blocked AO ray where all 64 saw the sky) raises the render's variance
    // with its mean, so it cannot fail a correct stage; the cap keeps a broken stage from
    // excusing itself by its noise.
    const glm::dvec3 oneRender(replicateVariance->at(b.x0, b.y0));
    const double replicates = input.replicates;
    variance = oneRender * (1.0 + 1.0 / replicates);
    if (ownPixels && input.imageVariance) {
      const glm::dvec3 own = independentTileVariance(*input.imageVariance, b);
      const glm::dvec3 cap = settings.ownVarianceCap * glm::max(oneRender, floor * floor);
      variance = glm::max(oneRender, glm::min(own, cap)) + oneRender / replicates;
    }
    if (ownBlock.degreesOfFreedom > 0.0) {
      const glm::dvec3 noiseless = settings.noiselessFraction * glm::abs(referenceMean);
      const glm::dvec3 cap = settings.ownNoiseCap * glm::max(oneRender, noiseless * noiseless);
      for (int c = 0; c < 3; ++c) {
        const double meanNoise = oneRender[c] / replicates;
        // The neighbourhood's noise ratio widens the replicates' variance (stable: many degrees
        // of freedom) ...
        const double ratio = std::min(ownBlock.neighbourhoodRatio[c], settings.ownNoiseCap);
        if (oneRender[c] * ratio + meanNoise > variance[c]) {
          variance[c] = oneRender[c] * ratio + meanNoise;
          degrees[c] = std::min(replicates - 1.0, ownBlock.neighbourhoodDegrees[c]);
        }
        // ... and the unit's own estimate, where larger still: a firefly, or noise where the
        // replicates have none (uniform directions under an open sky).
        const double own = std::min(ownBlock.variance[c], cap[c]);
        if (own + meanNoise > variance[c]) {
          variance[c] = own + meanNoise;
          degrees[c] =
              welchDegreesOfFreedom(own, ownBlock.degreesOfFreedom, meanNoise, replicates - 1.0);
        }
      }
    }
  } else {
    if (input.imageVariance) variance += independentTileVariance(*input.imageVariance, b);
    if (input.referenceVariance) variance += independentTileVariance(*input.referenceVariance, b);
    variance *= input.pixelCorrelation;
  }
  Unit unit;
  for (int c = 0; c < 3; ++c) {
    unit.t[c] = difference[c] / std::sqrt(std::max(variance[c], 0.0) + floor[c] * floor[c]);
    unit.p[c] = studentTTwoSidedP(unit.t[c], degrees[c]);
    unit.z[c] = studentTToNormal(unit.t[c], degrees[c]);
  }
  return unit;
}

// The note's noise ratio, like for like: the render's typical noise over a reference render's
// (the reference's jackknife is kept in the omnibus blocks' units).
void measureNoiseRatio(const ComparisonInput& input, int blockSize, Comparison& result) {
  if (!input.referenceJackknife || !(input.referenceTypicalNoise > 0.0) || !input.jackknife ||
      input.jackknife->size() < 2)
    return;
  const Image own = jackknifeBlockVariance(*input.jackknife, blockSize);
  result.noiseRatio =
      typicalNoise(own, *input.referenceJackknife, blockSize) / input.referenceTypicalNoise;
}

// Test 4 (image_comparison.h): how close the image is to the reference, against an exact image.
void measureCloseness(const ComparisonInput& input, const std::vector<TileBounds>& blockBounds,
                      bool blocks, Comparison& result) {
  const Image& oneRender =
      blocks && input.blockVariance ? *input.blockVariance : *input.tileVariance;
  double squared = 0.0, noise = 0.0, noiseSquared = 0.0;
  for (const TileBounds& b : blockBounds) {
    const glm::dvec3 difference = tileMean(*input.image, b) - tileMean(*input.reference, b);
    const glm::dvec3 meanVariance = glm::dvec3(oneRender.at(b.x0, b.y0)) / double(input.replicates);
    for (int c = 0; c < 3; ++c) {
      squared += difference[c] * difference[c];
      noise += meanVariance[c];
      noiseSquared += meanVariance[c] * meanVariance[c];
    }
  }
  if (!(noise > 0.0)) return;  // a reference without noise: nothing to be closer than
  result.closeness = squared / noise;
  // An exact image's Σ d² is Σ v_i χ²_1: about χ²_k · noise / k with k = noise² / Σ v_i².
  const double degrees = noise * noise / noiseSquared;
  result.closenessP = chiSquaredLowerTail(result.closeness * degrees, degrees);
}

}  // namespace

bool Comparison::passed(const ComparisonSettings& settings) const {
  return meanAgrees(settings) && !tooClose(settings) && !tooNoisy();
}

std::string Comparison::describe(const ComparisonSettings& settings) const {
  std::ostringstream out;
  for (const std::string& failure : hardFailures) out << failure << "\n";
  if (!hardFailures.empty()) return out.str();
  const bool tilesFail = worstTileP < settings.tileAlpha;
  const bool omnibusFails = omnibusP < settings.omnibusAlpha;
  if (omnibusFails && !tilesFail)
    out << "no single tile differs enough to fail on its own, but together they do: the "
           "difference is small and spread over the whole image (see the map of block z)\n";
  out << (failingTiles > 0 ? std::to_string(failingTiles) + " of " : "no tile of ") << tiles.size()
      << " tiles (" << tileSize << "x" << tileSize << " pixels) differ significantly; worst tile "
      << formatP(worstTileP) << " after correction for " << 3 * tiles.size()
      << " tests (fails below " << formatNumber(settings.tileAlpha) << ")\n";
  out << "whole image: omnibus " << formatP(omnibusP) << " (fails below "
      << formatNumber(settings.omnibusAlpha) << "); mean differs from the reference by "
      << formatNumber(100.0 * meanRelativeDifference) << "%\n";
  if (tooNoisy())
    out << "your render is " << formatNumber(noiseRatio)
        << " times as noisy as the reference's (both by the jackknife over their sample "
           "batches); this case allows at most "
        << formatNumber(noiseBound) << " times: " << requiredTechnique << "\n";
  else if (noiseRatio >= kNotedNoiseRatio)
    out << "your render is " << formatNumber(noiseRatio)
        << " times as noisy as the reference's (both by the jackknife over their sample "
           "batches): "
        << (noiseRatio < settings.ownNoiseCap
                ? "a valid method may be; the whole-image tests allow for it"
                : "the whole-image tests allow for no more than " +
                      formatNumber(settings.ownNoiseCap) + " times")
        << "\n";
  if (tooClose(settings))
    out << "too close to be true: the image differs from the reference " << formatNumber(closeness)
        << " times as much as the reference's own noise alone would make it differ (an image "
           "with no noise at all: about 1; this close: p = "
        << formatNumber(closenessP)
        << "). A render cannot come this close; a copy of the reference does\n";
  return out.str();
}

Comparison compareImages(const ComparisonInput& input, const ComparisonSettings& settings) {
  Comparison result;
  const Image& image = *input.image;
  const Image& reference = *input.reference;
  result.width = image.width;
  result.height = image.height;
  if (image.width != reference.width || image.height != reference.height) {
    result.hardFailures.push_back("the image is " + std::to_string(image.width) + "x" +
                                  std::to_string(image.height) + " pixels, the reference " +
                                  std::to_string(reference.width) + "x" +
                                  std::to_string(reference.height));
    return result;
  }
  for (const Color& c : image.pixels) {
    if (!isFinite(c))
      ++result.nonFinitePixels;
    else if (c.x < 0.0f || c.y < 0.0f || c.z < 0.0f)
      ++result.negativePixels;
  }
  if (result.nonFinitePixels > 0)
    result.hardFailures.push_back(std::to_string(result.nonFinitePixels) +
                                  " pixels are NaN or infinite");
  if (input.droppedSamples > 0)
    result.hardFailures.push_back(
        std::to_string(input.droppedSamples) +
        " radiance samples were NaN or infinite (the renderer dropped them; a correct stage "
        "never makes one here)");
  if (result.negativePixels > 0 && !input.negativeValuesAllowed)
    result.hardFailures.push_back(std::to_string(result.negativePixels) +
                                  " pixels are negative, which this filter cannot make from "
                                  "non-negative radiance");
  if (!result.hardFailures.empty()) return result;

  const bool replicated = input.tileVariance != nullptr;
  result.degreesOfFreedom =
      replicated ? input.replicates - 1.0 : std::numeric_limits<double>::infinity();
  result.tileSize = settings.tileSize;
  const std::vector<TileBounds> bounds = tilesOf(image.width, image.height, settings.tileSize);
  const double tests = 3.0 * bounds.size();
  result.tileThresholdP = sidakPerTestAlpha(settings.tileAlpha, tests);

  double smallestP = 1.0;
  const auto perRow = [&](int size) {
    return static_cast<size_t>((image.width + size - 1) / size);
  };
  const std::vector<OwnVariance> ownTiles =
      replicated ? ownVariances(input, bounds, perRow(settings.tileSize), *input.tileVariance)
                 : std::vector<OwnVariance>(bounds.size());
  for (size_t i = 0; i < bounds.size(); ++i) {
    const TileBounds& b = bounds[i];
    const Unit unit = unitStatistic(input, settings, result.degreesOfFreedom, b, input.tileVariance,
                                    true, ownTiles[i]);
    TileVerdict tile{b.x0, b.y0, b.x1, b.y1};
    for (int c = 0; c < 3; ++c) {
      tile.t[c] = static_cast<float>(unit.t[c]);
      tile.z[c] = static_cast<float>(unit.z[c]);
      tile.p = std::min(tile.p, unit.p[c]);
    }
    tile.failed = tile.p < result.tileThresholdP;
    result.failingTiles += tile.failed;
    smallestP = std::min(smallestP, tile.p);
    result.tiles.push_back(tile);
  }
  result.worstTileP = sidakFamilyP(smallestP, tests);

  // The omnibus tests add up blocks at least as large as the filter's reach, so that their
  // statistics are nearly independent, as the χ² sum assumes (small tiles under a wide filter
  // share most of their samples with their neighbours); what correlation remains is measured
  // on the replicates and divides the mean shift. Each block's z is clamped, so that one rare
  // huge sample cannot decide them either way.
  const bool blocks = input.blockVariance != nullptr || !replicated;
  const int blockSize = blocks ? settings.omnibusBlockSize : settings.tileSize;
  const std::vector<TileBounds> blockBounds = tilesOf(image.width, image.height, blockSize);
  glm::dvec3 sumZ(0.0), sumZ2(0.0);
  const Image* blockReplicateVariance =
      replicated && blocks ? input.blockVariance : input.tileVariance;
  const std::vector<OwnVariance> ownBlocks =
      replicated ? ownVariances(input, blockBounds, perRow(blockSize), *blockReplicateVariance)
                 : std::vector<OwnVariance>(blockBounds.size());
  for (size_t i = 0; i < blockBounds.size(); ++i) {
    const TileBounds& b = blockBounds[i];
    const Unit unit = unitStatistic(input, settings, result.degreesOfFreedom, b,
                                    blockReplicateVariance, false, ownBlocks[i]);
    const glm::dvec3 z = glm::clamp(unit.z, -settings.omnibusClamp, settings.omnibusClamp);
    TileVerdict block{b.x0, b.y0, b.x1, b.y1};
    block.z = Color(z);
    result.blocks.push_back(block);
    sumZ += z;
    sumZ2 += z * z;
  }
  const double count = static_cast<double>(blockBounds.size());
  double smallestOmnibus = 1.0;
  for (int c = 0; c < 3; ++c) {
    result.chiSquaredP[c] = chiSquaredUpperTail(sumZ2[c], count);
    result.meanShiftP[c] = studentTTwoSidedP(sumZ[c] / std::sqrt(count * input.blockCorrelation[c]),
                                             result.degreesOfFreedom);
    smallestOmnibus = std::min({smallestOmnibus, result.chiSquaredP[c], result.meanShiftP[c]});
  }
  result.omnibusP = std::min(1.0, 6.0 * smallestOmnibus);
  measureNoiseRatio(input, settings.omnibusBlockSize, result);
  result.noiseBound = input.noiseBound;
  result.requiredTechnique = input.requiredTechnique;
  if (replicated) measureCloseness(input, blockBounds, blocks, result);
  const double referenceMean = mean(reference);
  result.meanRelativeDifference =
      referenceMean != 0.0 ? (mean(image) - referenceMean) / referenceMean : 0.0;
  return result;
}

glm::dvec3 replicateBlockCorrelation(const std::vector<Image>& replicates, int blockSize) {
  const Image& first = replicates.front();
  const std::vector<TileBounds> blocks = tilesOf(first.width, first.height, blockSize);
  const double count = static_cast<double>(replicates.size());
  std::vector<std::vector<glm::dvec3>> means(blocks.size());  // [block][replicate]
  for (size_t b = 0; b < blocks.size(); ++b)
    for (const Image& replicate : replicates) means[b].push_back(tileMean(replicate, blocks[b]));
  std::vector<glm::dvec3> sums(replicates.size(), glm::dvec3(0.0));  // Σ_b z per replicate
  for (const std::vector<glm::dvec3>& block : means) {
    glm::dvec3 average(0.0), squares(0.0);
    for (const glm::dvec3& m : block) average += m / count;
    for (const glm::dvec3& m : block) squares += (m - average) * (m - average);
    const glm::dvec3 sd = glm::sqrt(squares / (count - 1.0));
    for (size_t r = 0; r < block.size(); ++r)
      for (int c = 0; c < 3; ++c)
        if (sd[c] > 0.0) sums[r][c] += (block[r][c] - average[c]) / sd[c];
  }
  glm::dvec3 variance(0.0);
  for (const glm::dvec3& s : sums) variance += s * s / (count - 1.0);  // the sums' mean is 0
  // Below 1 where blocks without noise (a background) add nothing to the sum: measured, not
  // assumed, like the rest of the reference.
  return glm::max(variance / double(blocks.size()), glm::dvec3(1e-6));
}

double smallestDetectableBias(const Image& mean, const Image& blockVariance, int blockSize,
                              int replicates, const glm::dvec3& blockCorrelation,
                              const ComparisonSettings& settings) {
  // Σ z over the blocks grows by b · Σ m / s; the test fails at |Σ z| / sqrt(n · correlation) =
  // z* (two-sided, Bonferroni over the six omnibus tests), half the time when that is the shift.
  const double threshold = -normalQuantile(settings.omnibusAlpha / 12.0);
  const std::vector<TileBounds> blocks = tilesOf(mean.width, mean.height, blockSize);
  double smallest = std::numeric_limits<double>::infinity();
  for (int c = 0; c < 3; ++c) {
    double shiftPerBias = 0.0;
    for (const TileBounds& b : blocks) {
      const double m = tileMean(mean, b)[c];
      const double floor = settings.relativeFloor * std::fabs(m) + settings.absoluteFloor;
      const double variance = blockVariance.at(b.x0, b.y0)[c] * (1.0 + 1.0 / replicates);
      shiftPerBias += std::fabs(m) / std::sqrt(variance + floor * floor);
    }
    if (shiftPerBias > 0.0)
      smallest = std::min(
          smallest, threshold * std::sqrt(blocks.size() * blockCorrelation[c]) / shiftPerBias);
  }
  return smallest;
}

double filterPixelCorrelation(double filterRadius) {
  const double reach = std::max(1.0, 2.0 * filterRadius);
  return reach * reach;
}

Image jackknifeBlockVariance(const std::vector<Image>& jackknife, int blockSize) {
  const Image& first = jackknife.front();
  return constantOverTiles(first.width, first.height, blockSize,
                           [&](const TileBounds& b) { return jackknifeVariance(jackknife, b); });
}

double typicalNoise(const Image& ownJackknife, const Image& referenceJackknife, int blockSize) {
  std::vector<double> ratios;
  for (const TileBounds& b :
       tilesOf(referenceJackknife.width, referenceJackknife.height, blockSize)) {
    const glm::dvec3 theirs(referenceJackknife.at(b.x0, b.y0));
    const double reference = theirs.x + theirs.y + theirs.z;
    if (!(reference > 0.0)) continue;
    const glm::dvec3 mine(ownJackknife.at(b.x0, b.y0));
    ratios.push_back((mine.x + mine.y + mine.z) / reference);
  }
  if (ratios.empty()) return 0.0;
  const auto middle = ratios.begin() + ratios.size() / 2;
  std::nth_element(ratios.begin(), middle, ratios.end());
  return *middle;
}

Image replicateTileVariance(const std::vector<Image>& replicates, int tileSize) {
  const Image& first = replicates.front();
  const double count = static_cast<double>(replicates.size());
  return constantOverTiles(first.width, first.height, tileSize, [&](const TileBounds& b) {
    std::vector<glm::dvec3> means;
    glm::dvec3 sum(0.0);
    for (const Image& replicate : replicates) sum += means.emplace_back(tileMean(replicate, b));
    const glm::dvec3 average = sum / count;
    glm::dvec3 squares(0.0);  // two passes: no cancellation when the variance is tiny
    for (const glm::dvec3& m : means) squares += (m - average) * (m - average);
    return squares / (count - 1.0);
  });
}

}  // namespace pathway
