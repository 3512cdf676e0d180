#include "grade/difference_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <vector>

#include "grade/diagnosis_candidates.h"
#include "grade/robust_fit.h"

namespace pathway {
namespace {

// A share of the difference beyond noise the chosen pattern must explain, or the cause is not
// named.
constexpr double kMinimumShare = 0.5;
// Pixels along the border left out of the diagnosis (the widest filter's reach, rounded up).
constexpr int kBorder = 4;
// `local` names at most this many tiles.
constexpr int kMostLocalTiles = 4;

// `noise` needs the render's own variance this many times the reference's, or less than 1/it.
constexpr double kNoiseRatio = 1.25;

// Differences whose neighbouring tiles correlate more than this have a shape: not `noise`.
constexpr double kMostNoiseCorrelation = 0.2;

// Σ y_i y_j / Σ y² over neighbouring tiles j of i (right or below, the same channel), the larger
// of the two: near 0 for noise, near 1 for a difference that varies slowly across the image.
double neighbourCorrelation(const Vector& y, size_t columns) {
  double right = 0.0, below = 0.0, squares = 0.0;
  for (size_t i = 0; i < y.size(); ++i) {
    squares += y[i] * y[i];
    if ((i / 3 + 1) % columns != 0 && i + 3 < y.size()) right += y[i] * y[i + 3];
    if (i + 3 * columns < y.size()) below += y[i] * y[i + 3 * columns];
  }
  return squares > 0.0 ? std::max(right, below) / squares : 0.0;
}

// The render's own variance estimate over the reference renders' own, summed over the tiles;
// 0 when either is missing.
double varianceRatio(const DiagnosisInput& input, const std::vector<TileBounds>& tiles) {
  const auto reference = input.patterns.find(pattern::kRenderVariance);
  if (!input.imageVariance || reference == input.patterns.end() || !reference->second) return 0.0;
  const Image& own = *input.imageVariance;
  const Image& theirs = *reference->second;
  if (own.width != theirs.width || own.height != theirs.height) return 0.0;
  double a = 0.0, b = 0.0;
  for (const TileBounds& t : tiles) {
    const glm::dvec3 mine = tileMean(own, t), expected = tileMean(theirs, t);
    a += mine.x + mine.y + mine.z;
    b += expected.x + expected.y + expected.z;
  }
  return a > 0.0 && b > 0.0 && std::isfinite(a) ? a / b : 0.0;
}

Diagnosis named(LikelyCause cause, double share, std::string explanation) {
  return {cause, share, std::move(explanation)};
}

// " (this pattern explains 83.8% of the difference beyond noise)"
std::string explaining(const char* what, double share) {
  return std::string(" (") + what + " explains " + percent(share) +
         " of the difference beyond noise)";
}

// Hard failures: the image cannot be fitted; say what they point at.
Diagnosis hardFailureDiagnosis(const DiagnosisInput& input, const Comparison& comparison,
                               int tileSize) {
  if (comparison.width != input.reference->width || comparison.height != input.reference->height)
    return named(LikelyCause::Unknown, 0.0, "the image has another size than the reference");
  if (comparison.nonFinitePixels > 0) {
    std::set<std::pair<int, int>> tiles;
    int firstX = -1, firstY = -1;
    for (int y = 0; y < input.image->height; ++y)
      for (int x = 0; x < input.image->width; ++x)
        if (!isFinite(input.image->at(x, y))) {
          if (firstX < 0) firstX = x, firstY = y;
          tiles.insert({x / tileSize, y / tileSize});
        }
    const std::string where =
        "first at pixel (" + std::to_string(firstX) + ", " + std::to_string(firstY) + ")";
    if (static_cast<int>(tiles.size()) <= kMostLocalTiles)
      return named(LikelyCause::Local, 1.0,
                   "NaN or infinite pixels in " + std::to_string(tiles.size()) + " tile(s), " +
                       where + ": look for a division by a pdf or a length that can be 0 there");
    return named(LikelyCause::Unknown, 0.0,
                 "NaN or infinite pixels all over the image (" + where +
                     "): look for a division by zero or the root of a negative number");
  }
  if (comparison.negativePixels > 0)
    return named(LikelyCause::Unknown, 0.0,
                 "negative pixels: some radiance or weight comes out below zero");
  return named(LikelyCause::Noise, 1.0,
               "some samples were NaN or infinite and were dropped, so the image lacks them: "
               "look for a division by a pdf or a length that can be 0, or a direction "
               "built from a vector that can be 0 (a ray with a NaN direction sees nothing)");
}

}  // namespace

const char* likelyCauseName(LikelyCause cause) {
  switch (cause) {
    case LikelyCause::Scale:
      return "scale";
    case LikelyCause::Edges:
      return "edges";
    case LikelyCause::Shift:
      return "shift";
    case LikelyCause::Lit:
      return "lit";
    case LikelyCause::Indirect:
      return "indirect";
    case LikelyCause::Background:
      return "background";
    case LikelyCause::Occlusion:
      return "occlusion";
    case LikelyCause::Noise:
      return "noise";
    case LikelyCause::Local:
      return "local";
    case LikelyCause::Unknown:
      break;
  }
  return "unknown";
}

std::string Diagnosis::line() const {
  return std::string("likely cause: ") + likelyCauseName(cause) + " \u2014 " + explanation;
}

Diagnosis diagnoseDifference(const DiagnosisInput& input, const Comparison& comparison,
                             const ComparisonSettings& settings) {
  const int tileSize = input.tileSize > 0 ? input.tileSize : settings.tileSize;
  if (!comparison.hardFailures.empty()) return hardFailureDiagnosis(input, comparison, tileSize);
  const Image& image = *input.image;
  const Image& reference = *input.reference;
  // The tiles away from the image's border: there a filter reaches past the image, and the
  // differences of a misplaced splat are of a kind of their own that would drown the rest.
  std::vector<TileBounds> tiles;
  for (const TileBounds& t : tilesOf(image.width, image.height, tileSize))
    if (t.x0 >= kBorder && t.y0 >= kBorder && t.x1 <= image.width - kBorder &&
        t.y1 <= image.height - kBorder)
      tiles.push_back(t);
  if (tiles.empty()) return named(LikelyCause::Unknown, 0.0, "the image is too small to tell");
  size_t tileColumns = 0;
  while (tileColumns < tiles.size() && tiles[tileColumns].y0 == tiles.front().y0) ++tileColumns;

  // Whitened differences y = d / σ, σ² the variance of the difference of one render's tile mean
  // and the reference's (as the tile test has it, without the render's own variance).
  Vector y, weight;
  for (const TileBounds& t : tiles) {
    const glm::dvec3 d = tileMean(image, t) - tileMean(reference, t);
    const glm::dvec3 floor =
        settings.relativeFloor * glm::abs(tileMean(reference, t)) + settings.absoluteFloor;
    const glm::dvec3 v =
        input.tileVariance ? glm::dvec3(input.tileVariance->at(t.x0, t.y0)) : glm::dvec3(0.0);
    const double replicates = std::max(1, input.replicates);
    for (int c = 0; c < 3; ++c) {
      const double w = 1.0 / std::sqrt(v[c] * (1.0 + 1.0 / replicates) + floor[c] * floor[c]);
      weight.push_back(w);
      y.push_back(d[c] * w);
    }
  }
  const double n = static_cast<double>(y.size());
  const double lossOfY = totalHuberLoss(y);
  // What noise alone would give is about n; what lies beyond it is what a cause must explain.
  const double excess = std::max(lossOfY - n, 1.0);
  const double perParameter = std::log(n);  // BIC's price of one fitted number

  Diagnosis best = named(LikelyCause::Unknown, 0.0, "");
  double bestScore = 0.0;
  for (const Candidate& candidate : candidates(input, tiles)) {
    std::vector<Vector> columns;
    for (const Vector& p : candidate.patterns) {
      Vector whitened(p.size());
      for (size_t i = 0; i < p.size(); ++i) whitened[i] = p[i] * weight[i];
      columns.push_back(std::move(whitened));
    }
    Fit fit;
    if (candidate.fitted) {
      fit = robustFit(y, columns, lossOfY);
    } else {
      Vector residual = y;
      for (size_t i = 0; i < y.size(); ++i) residual[i] -= columns.front()[i];
      fit = {lossOfY - totalHuberLoss(residual), {1.0}};
    }
    if (fit.coefficients.empty()) continue;  // a pattern that is zero here (no background, ...)
    const double score =
        fit.explained -
        perParameter * double((candidate.fitted ? columns.size() : 0) + candidate.searchedNumbers);
    if (score > bestScore) {
      bestScore = score;
      best = named(candidate.cause, std::min(1.0, fit.explained / excess),
                   candidate.explain(fit.coefficients));
    }
  }

  // `local`: a few tiles whose squares hold the difference. Picking k of n costs more than
  // fitting k numbers: about 2 ln n each (the largest of n squares of noise is near 2 ln n).
  std::vector<std::pair<double, size_t>> squares;
  for (size_t i = 0; i < y.size(); ++i) squares.push_back({huberLoss(y[i]), i});
  const size_t most = std::min<size_t>(squares.size(), 3 * kMostLocalTiles);
  std::partial_sort(squares.begin(), squares.begin() + most, squares.end(),
                    std::greater<std::pair<double, size_t>>());
  std::set<size_t> localTiles;
  double localExplained = 0.0;
  for (size_t k = 0; k < most; ++k) {
    localTiles.insert(squares[k].second / 3);
    if (localTiles.size() > static_cast<size_t>(kMostLocalTiles)) break;
    localExplained += squares[k].first;
    const double score = localExplained - (2.0 * perParameter + 2.0) * double(k + 1);
    if (score > bestScore) {
      const TileBounds& worst = tiles[squares[0].second / 3];
      bestScore = score;
      best = named(LikelyCause::Local, std::min(1.0, localExplained / excess),
                   std::to_string(localTiles.size()) + " tile(s) hold most of the difference, " +
                       "the worst at pixels (" + std::to_string(worst.x0) + ", " +
                       std::to_string(worst.y0) + ") to (" + std::to_string(worst.x1 - 1) + ", " +
                       std::to_string(worst.y1 - 1) +
                       "): look for rare huge samples there (a division by a tiny pdf or "
                       "distance) or a value that breaks one kind of hit");
    }
  }

  // `noise`: the render's own variance against the reference renders'. A render v times as noisy
  // makes about n·v of loss, so v - 1 of it per value is the noise's share of the excess.
  const double variance = varianceRatio(input, tiles);
  const double noiseShare = variance > 1.0 ? std::min(1.0, n * (variance - 1.0) / excess) : 0.0;
  const bool noisier = variance > kNoiseRatio || (variance > 0.0 && variance < 1.0 / kNoiseRatio);
  if (noisier && noiseShare >= kMinimumShare && noiseShare > best.explainedShare)
    return named(LikelyCause::Noise, noiseShare,
                 "the mean agrees but the noise does not (your render's own variance is " +
                     ratio(variance) + " times the reference's): " + kSamplingHint +
                     explaining("this", noiseShare));
  if (bestScore > 0.0 && best.explainedShare >= kMinimumShare) {
    best.explanation += explaining("this pattern", best.explainedShare);
    return best;
  }
  // Without the renders' own variances: far more difference than noise, no pattern for it, and
  // neighbouring tiles that do not move together.
  if (variance <= 0.0 && lossOfY - n > 5.0 * std::sqrt(2.0 * n) &&
      neighbourCorrelation(y, tileColumns) < kMostNoiseCorrelation)
    return named(LikelyCause::Noise, 1.0 - best.explainedShare,
                 "the differences follow no pattern, and there are " + ratio(lossOfY / n) +
                     " times as many as noise makes: the mean agrees but the noise does not; " +
                     kSamplingHint);
  const std::string bestName =
      best.explanation.empty() ? "none" : std::string(likelyCauseName(best.cause));
  return named(LikelyCause::Unknown, 0.0,
               "no pattern explains most of the difference (the closest, " + bestName +
                   ", explains " + percent(best.explainedShare) +
                   "); compare your image with the reference in the viewer");
}

}  // namespace pathway
