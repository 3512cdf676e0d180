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

Unit unitStatistic(const ComparisonInput& input, const ComparisonSettings& settings,
                   double degreesOfFreedom, const TileBounds& b, const Image* replicateVariance,
                   bool ownVarianceExcuses) {
  const glm::dvec3 difference = tileMean(*input.image, b) - tileMean(*input.reference, b);
  // Differences this small never count, even where the reference has no noise at all.
  const glm::dvec3 floor =
      settings.relativeFloor * glm::abs(tileMean(*input.reference, b)) + settings.absoluteFloor;
  glm::dvec3 variance(0.0);
  if (replicateVariance) {
    // The submission is one more render like the R replicates; the reference mean is their
    // average: Var(m_image - m_reference) = V (1 + 1/R). Where the render's own estimate is
    // larger, it is used instead, up to a cap: a rare sample that the replicates happened to
    // miss (a firefly; one blocked AO ray where all 64 saw the sky) raises the render's variance
    // with its mean, so it cannot fail a correct stage; the cap keeps a broken stage from
    // excusing itself by its noise.
    const glm::dvec3 oneRender(replicateVariance->at(b.x0, b.y0));
    const glm::dvec3 own = input.imageVariance && ownVarianceExcuses
                               ? independentTileVariance(*input.imageVariance, b)
                               : glm::dvec3(0.0);
    const glm::dvec3 cap = settings.ownVarianceCap * glm::max(oneRender, floor * floor);
    variance = glm::max(oneRender, glm::min(own, cap)) + oneRender / double(input.replicates);
  } else {
    if (input.imageVariance) variance += independentTileVariance(*input.imageVariance, b);
    if (input.referenceVariance) variance += independentTileVariance(*input.referenceVariance, b);
    variance *= input.pixelCorrelation;
  }
  Unit unit;
  for (int c = 0; c < 3; ++c) {
    unit.t[c] = difference[c] / std::sqrt(std::max(variance[c], 0.0) + floor[c] * floor[c]);
    unit.p[c] = studentTTwoSidedP(unit.t[c], degreesOfFreedom);
    unit.z[c] = studentTToNormal(unit.t[c], degreesOfFreedom);
  }
  return unit;
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
  return hardFailures.empty() && worstTileP >= settings.tileAlpha &&
         omnibusP >= settings.omnibusAlpha && !tooClose(settings);
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
  for (const TileBounds& b : bounds) {
    const Unit unit =
        unitStatistic(input, settings, result.degreesOfFreedom, b, input.tileVariance, true);
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
  // on the replicates and divides the mean shift. They use the replicates' variance alone, and
  // each block's z is clamped, so that one rare huge sample cannot decide them either way.
  const bool blocks = input.blockVariance != nullptr || !replicated;
  const int blockSize = blocks ? settings.omnibusBlockSize : settings.tileSize;
  const std::vector<TileBounds> blockBounds = tilesOf(image.width, image.height, blockSize);
  glm::dvec3 sumZ(0.0), sumZ2(0.0);
  for (const TileBounds& b : blockBounds) {
    const Unit unit =
        unitStatistic(input, settings, result.degreesOfFreedom, b,
                      replicated && blocks ? input.blockVariance : input.tileVariance, false);
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

double filterPixelCorrelation(double filterRadius) {
  const double reach = std::max(1.0, 2.0 * filterRadius);
  return reach * reach;
}

Image replicateTileVariance(const std::vector<Image>& replicates, int tileSize) {
  const Image& first = replicates.front();
  Image result(first.width, first.height);
  const double count = static_cast<double>(replicates.size());
  for (const TileBounds& b : tilesOf(first.width, first.height, tileSize)) {
    std::vector<glm::dvec3> means;
    glm::dvec3 sum(0.0);
    for (const Image& replicate : replicates) sum += means.emplace_back(tileMean(replicate, b));
    const glm::dvec3 average = sum / count;
    glm::dvec3 squares(0.0);  // two passes: no cancellation when the variance is tiny
    for (const glm::dvec3& m : means) squares += (m - average) * (m - average);
    const glm::dvec3 variance = squares / (count - 1.0);
    for (int y = b.y0; y < b.y1; ++y)
      for (int x = b.x0; x < b.x1; ++x) result.at(x, y) = Color(variance);
  }
  return result;
}

}  // namespace pathway
