#include "grade/difference_diagnosis.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <set>
#include <vector>

namespace pathway {
namespace {

// A share of the difference beyond noise the chosen pattern must explain, or the cause is not
// named.
constexpr double kMinimumShare = 0.5;
// Moves searched: up to kShiftSteps steps of 1/kShiftStepsPerPixel pixel each way.
constexpr int kShiftSteps = 4;
constexpr int kShiftStepsPerPixel = 4;
// Pixels along the border left out of the diagnosis (the widest filter's reach, rounded up).
constexpr int kBorder = 4;
// `local` names at most this many tiles.
constexpr int kMostLocalTiles = 4;

// `noise` needs the render's own variance this many times the reference's, or less than 1/it.
constexpr double kNoiseRatio = 1.25;

// Differences whose neighbouring tiles correlate more than this have a shape: not `noise`.
constexpr double kMostNoiseCorrelation = 0.2;

using Vector = std::vector<double>;  // one value per tile and channel

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

// One number as printf formats it.
std::string formatted(const char* format, double value) {
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

std::string percent(double fraction) {
  return formatted("%.1f%%", 100.0 * std::fabs(fraction));
}
std::string ratio(double value) {
  return formatted("%.2f", value);
}
std::string signedNumber(double value) {
  return formatted("%+.2f", value);
}

// Finite differences at pixel level, clamped at the borders.
Image derivative(const Image& r, const std::function<Color(const Image&, int, int)>& stencil) {
  Image out(r.width, r.height);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) out.at(x, y) = stencil(r, x, y);
  return out;
}

Color clamped(const Image& r, int x, int y) {
  return r.at(std::clamp(x, 0, r.width - 1), std::clamp(y, 0, r.height - 1));
}

Vector tileVector(const Image& image, const std::vector<TileBounds>& tiles) {
  Vector v;
  v.reserve(3 * tiles.size());
  for (const TileBounds& t : tiles) {
    const glm::dvec3 m = tileMean(image, t);
    v.insert(v.end(), {m.x, m.y, m.z});
  }
  return v;
}

// Huber's loss, doubled so that it is y² for small y (noise alone gives about 1 per value): a
// few tiles far out, which heavy-tailed Monte Carlo noise makes, weigh like a line, not a square,
// so they cannot outweigh a pattern that explains all the others.
constexpr double kHuberLimit = 3.0;
double loss(double r) {
  const double a = std::fabs(r);
  return a <= kHuberLimit ? r * r : 2.0 * kHuberLimit * a - kHuberLimit * kHuberLimit;
}

double totalLoss(const Vector& r) {
  double sum = 0.0;
  for (double value : r) sum += loss(value);
  return sum;
}

// Weighted least squares: solves (Xᵀ W X) β = Xᵀ W y. Empty when the columns are degenerate.
std::vector<double> solve(const Vector& y, const Vector& w, const std::vector<Vector>& columns) {
  const size_t k = columns.size();
  std::vector<std::vector<double>> a(k, std::vector<double>(k + 1, 0.0));  // [Gram | Xᵀy]
  for (size_t i = 0; i < k; ++i) {
    for (size_t j = 0; j < k; ++j)
      for (size_t n = 0; n < y.size(); ++n) a[i][j] += w[n] * columns[i][n] * columns[j][n];
    for (size_t n = 0; n < y.size(); ++n) a[i][k] += w[n] * columns[i][n] * y[n];
  }
  const std::vector<std::vector<double>> gram = a;
  for (size_t i = 0; i < k; ++i) {  // Gaussian elimination with partial pivoting
    size_t pivot = i;
    for (size_t r = i + 1; r < k; ++r)
      if (std::fabs(a[r][i]) > std::fabs(a[pivot][i])) pivot = r;
    std::swap(a[i], a[pivot]);
    if (!(std::fabs(a[i][i]) > 1e-12 * (1.0 + std::fabs(gram[i][i])))) return {};
    for (size_t r = 0; r < k; ++r) {
      if (r == i) continue;
      const double f = a[r][i] / a[i][i];
      for (size_t c = i; c <= k; ++c) a[r][c] -= f * a[i][c];
    }
  }
  std::vector<double> beta;
  for (size_t i = 0; i < k; ++i) beta.push_back(a[i][k] / a[i][i]);
  return beta;
}

// A robust fit of y by the columns (all whitened): Huber regression by iteratively reweighted
// least squares. `explained` is how much it lowers the total loss.
struct Fit {
  double explained = 0.0;
  std::vector<double> coefficients;
};

Fit robustFit(const Vector& y, const std::vector<Vector>& columns, double lossOfY) {
  constexpr int kIterations = 8;
  Vector w(y.size(), 1.0), r(y.size());
  Fit fit;
  for (int iteration = 0; iteration < kIterations; ++iteration) {
    fit.coefficients = solve(y, w, columns);
    if (fit.coefficients.empty()) return {};
    for (size_t n = 0; n < y.size(); ++n) {
      r[n] = y[n];
      for (size_t i = 0; i < columns.size(); ++i) r[n] -= fit.coefficients[i] * columns[i][n];
      w[n] = std::fabs(r[n]) <= kHuberLimit ? 1.0 : kHuberLimit / std::fabs(r[n]);
    }
  }
  fit.explained = lossOfY - totalLoss(r);
  return fit;
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

// One candidate cause: its patterns (tile means, not yet whitened) and how to say what the
// fitted coefficients mean.
struct Candidate {
  LikelyCause cause;
  std::vector<Vector> patterns;
  std::function<std::string(const std::vector<double>&)> explain;
  int searchedNumbers = 0;  // numbers chosen by a search before the fit, each priced as fitted
  bool fitted = true;       // false: the pattern is the difference itself, coefficient 1
};

// The reference moved right by sx and down by sy pixels (bilinear, clamped at the borders).
Image shifted(const Image& r, double sx, double sy) {
  Image out(r.width, r.height);
  for (int y = 0; y < r.height; ++y)
    for (int x = 0; x < r.width; ++x) {
      const double fx = x - sx, fy = y - sy;
      const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
      const float ax = static_cast<float>(fx - x0), ay = static_cast<float>(fy - y0);
      out.at(x, y) = (1 - ay) * ((1 - ax) * clamped(r, x0, y0) + ax * clamped(r, x0 + 1, y0)) +
                     ay * ((1 - ax) * clamped(r, x0, y0 + 1) + ax * clamped(r, x0 + 1, y0 + 1));
    }
  return out;
}

// What the messages of several candidates point at, said once.
constexpr const char* kFilterHint =
    "look at the filter's profile and radius, and at which pixels a sample's splat reaches";
constexpr const char* kSamplingHint =
    "look at how samples are drawn (which dimensions, which directions for which pdf) or "
    "whether some are dropped";

std::string movedBy(double sx, double sy) {
  return "the image is moved by about (" + signedNumber(sx) + ", " + signedNumber(sy) +
         ") pixels (right, down) against the reference: look at where a pixel's centre is and "
         "which pixels a sample reaches";
}

std::string brighterOrDarker(double coefficient) {
  return coefficient > 0 ? "too bright" : "too dark";
}

std::vector<Candidate> candidates(const DiagnosisInput& input,
                                  const std::vector<TileBounds>& tiles) {
  const Image& r = *input.reference;
  std::vector<Candidate> list;
  list.push_back({LikelyCause::Scale, {tileVector(r, tiles)}, [](const std::vector<double>& c) {
                    return "the whole image is " + percent(c[0]) +
                           (c[0] > 0 ? " brighter" : " darker") +
                           " than the reference, by one factor: look for a constant that is "
                           "missing or extra, such as 1/pi, a cosine or a pdf";
                  }});
  const Image laplacian = derivative(r, [](const Image& i, int x, int y) {
    return clamped(i, x + 1, y) + clamped(i, x - 1, y) + clamped(i, x, y + 1) +
           clamped(i, x, y - 1) - 4.0f * i.at(x, y);
  });
  list.push_back(
      {LikelyCause::Edges, {tileVector(laplacian, tiles)}, [](const std::vector<double>& c) {
         // image ≈ R + a ∇²R: a > 0 spreads each edge (blur), a < 0 steepens it.
         return std::string("the differences sit at edges: the image is ") +
                (c[0] > 0 ? "blurrier" : "sharper") + " than the reference there; " + kFilterHint;
       }});
  const Image dx = derivative(r, [](const Image& i, int x, int y) {
    return 0.5f * (clamped(i, x + 1, y) - clamped(i, x - 1, y));
  });
  const Image dy = derivative(r, [](const Image& i, int x, int y) {
    return 0.5f * (clamped(i, x, y + 1) - clamped(i, x, y - 1));
  });
  list.push_back({LikelyCause::Shift,
                  {tileVector(dx, tiles), tileVector(dy, tiles)},
                  [](const std::vector<double>& c) {
                    // image ≈ R + a·∇R = R(p + a): the image shows what the reference shows a
                    // further on, so it is moved by -a (to first order: it reads small moves across
                    // hard edges short).
                    return movedBy(-c[0], -c[1]);
                  }});
  // A move is searched on a grid of fractions of a pixel (a first-order fit of a gradient
  // misreads moves across hard edges); the search costs two more fitted numbers.
  for (int j = -kShiftSteps; j <= kShiftSteps; ++j)
    for (int i = -kShiftSteps; i <= kShiftSteps; ++i) {
      if (i == 0 && j == 0) continue;
      const double sx = double(i) / kShiftStepsPerPixel, sy = double(j) / kShiftStepsPerPixel;
      Image moved = shifted(r, sx, sy);
      for (size_t p = 0; p < moved.pixels.size(); ++p) moved.pixels[p] -= r.pixels[p];
      list.push_back({LikelyCause::Shift,
                      {tileVector(moved, tiles)},
                      [sx, sy](const std::vector<double>&) { return movedBy(sx, sy); },
                      2,
                      false});
    }
  const size_t fromImage = list.size();
  auto layer = [&](const char* name) -> const Image* {
    const auto it = input.patterns.find(name);
    return it != input.patterns.end() && it->second && it->second->width == r.width &&
                   it->second->height == r.height
               ? it->second
               : nullptr;
  };
  const Image* direct = layer(pattern::kDirect);
  const Image* indirect = layer(pattern::kIndirect);
  // Where a stage gathers light from the emitters: stage 5 samples them (NEE), stage 4 finds
  // them with its branches.
  const std::string gathering =
      input.stage == 4
          ? "look at the weight of a branch that reaches an emitter: the BRDF, cos theta, the "
            "pdf, the average over the N branches"
      : !input.nextEventEstimation
          ? "this case runs without next-event estimation, so look at a path that hits an "
            "emitter: the emission it adds, and the weight of the bounce that found it (BRDF, "
            "cos theta, pdf)"
          : "look at next-event estimation: how an emitter and a point on it are picked and "
            "their pdf, both cosines and the distance, the shadow ray, one-sided emitters";
  if (direct)
    list.push_back(
        {LikelyCause::Lit, {tileVector(*direct, tiles)}, [gathering](const std::vector<double>& c) {
           return "the differences are where light arrives straight from the "
                  "emitters (that light " +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) + "): " + gathering;
         }});
  if (direct && indirect) {
    Image lit = *direct;
    for (size_t p = 0; p < lit.pixels.size(); ++p) lit.pixels[p] += indirect->pixels[p];
    list.push_back(
        {LikelyCause::Lit, {tileVector(lit, tiles)}, [gathering](const std::vector<double>& c) {
           return "the differences are wherever light from the emitters arrives, "
                  "directly or after bounces (" +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "), but not on the emitters themselves: " + gathering;
         }});
  }
  for (const auto& name : {pattern::directFrom, pattern::litFrom}) {
    std::vector<Vector> perEmitter;
    for (size_t k = 0; const Image* alone = layer(name(k).c_str()); ++k)
      perEmitter.push_back(tileVector(*alone, tiles));
    if (perEmitter.size() < 2) continue;
    list.push_back({LikelyCause::Lit, perEmitter, [gathering](const std::vector<double>& c) {
                      std::string factors;
                      for (size_t k = 0; k < c.size(); ++k)
                        factors += (k ? ", " : "") + percent(c[k]) + " " + brighterOrDarker(c[k]);
                      return "the differences are where light from the emitters arrives, by a "
                             "factor of each emitter's own (" +
                             factors + "): " + gathering +
                             "; in particular whether an emitter's pdf is that of the rule that "
                             "picked it";
                    }});
  }
  if (indirect)
    list.push_back(
        {LikelyCause::Indirect, {tileVector(*indirect, tiles)}, [](const std::vector<double>& c) {
           return "the differences are in light that arrives after two or more "
                  "bounces (" +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "): look at the continuation ray and its weight, Russian "
                  "roulette's 1/q, and where paths stop";
         }});
  if (const Image* escaped = layer(pattern::kEscaped))
    list.push_back(
        {LikelyCause::Background, {tileVector(*escaped, tiles)}, [](const std::vector<double>& c) {
           return "the differences are where camera rays leave the scene (the "
                  "background " +
                  percent(c[0]) + " " + brighterOrDarker(c[0]) +
                  "): look at what a ray that hits nothing returns";
         }});
  if (const Image* occluded = layer(pattern::kOccluded))
    list.push_back(
        {LikelyCause::Occlusion, {tileVector(*occluded, tiles)}, [](const std::vector<double>& c) {
           // image ≈ R + a (U - R): the occluded part U - R shrinks by the factor a.
           return "the differences follow occlusion, in corners and near contacts "
                  "(the image there is " +
                  percent(c[0]) + (c[0] > 0 ? " less" : " more") +
                  " occluded than it should be): look at the AO ray's length, its "
                  "directions and their pdf, and where the ray starts";
         }});
  for (const auto& [name, rays] : {std::pair{pattern::kLongerRays, "twice as long"},
                                   std::pair{pattern::kUnlimitedRays, "of any length"}})
    if (const Image* longer = layer(name))
      list.push_back({LikelyCause::Occlusion,
                      {tileVector(*longer, tiles)},
                      [rays = std::string(rays)](const std::vector<double>& c) {
                        // image ≈ R + a (A' - R): a = 1 is AO with the longer rays.
                        return "the differences follow occlusion: the image looks like AO with "
                               "rays " +
                               rays + " (fitted " + ratio(c[0]) +
                               " of the way there): look at the AO ray's length (tMax) and how "
                               "it is passed on";
                      }});
  const Image* movedRight = layer(pattern::kMovedRight);
  const Image* movedDown = layer(pattern::kMovedDown);
  if (movedRight && movedDown)
    list.push_back({LikelyCause::Shift,
                    {tileVector(*movedRight, tiles), tileVector(*movedDown, tiles)},
                    [](const std::vector<double>& c) { return movedBy(c[0], c[1]); }});
  if (const Image* wider = layer(pattern::kWiderFilter)) {
    // The filter's width and, beside it, the reference's Laplacian: a profile of another shape
    // moves light at edges as neither does alone.
    list.push_back({LikelyCause::Edges,
                    {tileVector(*wider, tiles), tileVector(laplacian, tiles)},
                    [](const std::vector<double>& c) {
                      return std::string(
                                 "the differences sit at edges: the filter's profile "
                                 "has another shape (") +
                             (c[0] > 0 ? "wider" : "narrower") +
                             " than it should be, in effect); look at the filter's formula, its "
                             "radius, and which pixels a sample's splat reaches";
                    }});
    list.push_back(
        {LikelyCause::Edges, {tileVector(*wider, tiles)}, [](const std::vector<double>& c) {
           // 1.25 / 0.8 is e^0.446: a = 1 is a filter e^0.446 times as wide.
           return "the differences sit at edges: the image looks as if its filter were about " +
                  ratio(std::exp(0.446 * c[0])) + " times as wide as it should be; " + kFilterHint;
         }});
  }
  // A mask's light may be off by a factor that changes across the image (a pdf that is wrong for
  // one emitter, a cosine left out): the same mask times a smooth field, 1, u, v, u², uv, v² in
  // image coordinates, with its price in fitted numbers.
  const size_t rendered = list.size();
  for (size_t i = fromImage; i < rendered; ++i) {
    if (list[i].patterns.size() != 1 || list[i].cause == LikelyCause::Shift ||
        list[i].cause == LikelyCause::Edges)
      continue;
    Candidate modulated = list[i];
    const Vector base = modulated.patterns.front();
    for (int term = 1; term < 6; ++term) {
      Vector column(base.size());
      for (size_t k = 0; k < base.size(); ++k) {
        const TileBounds& t = tiles[k / 3];
        const double u = (t.x0 + t.x1) / double(r.width) - 1.0;
        const double v = (t.y0 + t.y1) / double(r.height) - 1.0;
        const double field[6] = {1.0, u, v, u * u, u * v, v * v};
        column[k] = base[k] * field[term];
      }
      modulated.patterns.push_back(std::move(column));
    }
    const auto explain = modulated.explain;
    modulated.explain = [explain](const std::vector<double>& c) {
      // The factor varies across the image: say its average (u and v run over [-1, 1], where u²
      // and v² average 1/3 and u, v, uv 0), not its constant term, which may be near 0.
      return explain({c[0] + (c[3] + c[5]) / 3.0}) + ", unevenly across the image";
    };
    list.push_back(std::move(modulated));
  }
  // The patterns rendered with the reference stages first: where one explains as much as a
  // pattern read off the reference image, it says more.
  std::rotate(list.begin(), list.begin() + static_cast<std::ptrdiff_t>(fromImage), list.end());
  return list;
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
               "look for a division by a pdf that can be 0");
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
  const double lossOfY = totalLoss(y);
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
      fit = {lossOfY - totalLoss(residual), {1.0}};
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
  for (size_t i = 0; i < y.size(); ++i) squares.push_back({loss(y[i]), i});
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
