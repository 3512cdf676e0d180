// What kind of bug a failing image shows, read from the difference to the reference alone (never
// from the code). Each candidate cause is a pattern the difference could follow: the reference
// itself (one factor off), its Laplacian (sharper or blurrier at edges), its gradient (moved by a
// fraction of a pixel), and masks the grading reference stores beside its mean (direct light,
// light after bounces, escaped camera rays, occlusion). Each is fitted to the tile differences
// by weighted least squares, the weights being the reference's own tile noise; the cause is the
// pattern that explains most of the difference beyond noise, with a penalty per fitted number,
// and only when it explains at least half of it. A difference that nothing explains but that is
// far above the noise is `noise`; otherwise the answer is `unknown`.
// Three files: the candidates and their messages (diagnosis_candidates.h), the robust fit
// (robust_fit.h), and the decision (difference_diagnosis.cpp).
#pragma once

#include <cstddef>
#include <map>
#include <string>

#include "film/film.h"
#include "grade/image_comparison.h"

namespace pathway {

enum class LikelyCause {
  Scale,
  Edges,
  Shift,
  Lit,
  Indirect,
  Background,
  Occlusion,
  Noise,
  Local,
  Unknown
};

// "scale", "edges", ... as reports and results.json write them.
const char* likelyCauseName(LikelyCause cause);

// Masks a grading reference may hold beside its mean, by layer name (grading_reference.h makes
// them). Each is an image of the same size; a missing one only removes its candidate.
namespace pattern {
constexpr const char* kPrefix = "pattern.";  // every pattern layer's name starts with it
// Not a pattern to fit: the mean of the reference renders' own per-pixel variance estimates, which
// a render's own estimate is held against before its difference is called `noise`.
constexpr const char* kRenderVariance = "pattern.renderVariance";
constexpr const char* kMovedRight = "pattern.movedRight";    // image moved 1 pixel right, minus it
constexpr const char* kMovedDown = "pattern.movedDown";      // the same, down
constexpr const char* kWiderFilter = "pattern.widerFilter";  // filter 1.25x minus 0.8x as wide
// The image rendered moved by (i/2, j/2) pixels (right, down), i, j in {-1, 0, 1}, minus the
// reference: a half-pixel move exactly, where the stripes are finer than a pixel's first order.
inline std::string movedByHalves(int i, int j) {
  return "pattern.moved." + std::to_string(i) + "." + std::to_string(j);
}
// Light after one bounce (from the emitters, and from the background where there is one), and
// after two or more.
constexpr const char* kDirect = "pattern.direct";
constexpr const char* kIndirect = "pattern.indirect";
// Direct light of emitter (emissive material) k alone: "pattern.direct.0", ...
inline std::string directFrom(size_t k) {
  return "pattern.direct." + std::to_string(k);
}
// All the light of emitter k alone, directly or after bounces, but not the emitter itself.
inline std::string litFrom(size_t k) {
  return "pattern.lit." + std::to_string(k);
}
// (Each emitter's masks hold the background's light too, where there is one.)
constexpr const char* kEscaped = "pattern.escaped";  // the background camera rays see
// The background's light on surfaces (every emitter dark): after any number of bounces, and
// after exactly one.
constexpr const char* kSkyLit = "pattern.skyLit";
constexpr const char* kSkyLitOnce = "pattern.skyLitOnce";
// The case one bounce deeper, minus the reference.
constexpr const char* kOneBounceMore = "pattern.oneBounceMore";
constexpr const char* kOccluded = "pattern.occluded";          // unoccluded AO minus the reference
constexpr const char* kLongerRays = "pattern.aoLonger";        // AO, rays twice as long, minus it
constexpr const char* kUnlimitedRays = "pattern.aoUnlimited";  // AO, rays of any length, minus it
}  // namespace pattern

struct DiagnosisInput {
  const Image* image = nullptr;          // the render
  const Image* reference = nullptr;      // the reference's mean
  const Image* tileVariance = nullptr;   // one render's tile-mean variance (grading_reference.h)
  const Image* imageVariance = nullptr;  // the render's own per-pixel variance estimate
  int replicates = 0;                    // behind the reference's mean
  int tileSize = 0;
  int stage = 0;  // the stage graded (0: not a stage), for what the explanations point at
  // The render sampled the emitters (stage 5's option with the NextEventEstimation role): with
  // it off, light from the emitters comes from paths that hit them, and nothing may point at NEE.
  bool nextEventEstimation = true;
  std::map<std::string, const Image*> patterns;  // by pattern:: name
};

struct Diagnosis {
  LikelyCause cause = LikelyCause::Unknown;
  double explainedShare = 0.0;  // of the difference beyond noise, by the chosen pattern
  std::string explanation;      // a sentence for the student: where, how much, what to look at

  // "likely cause: scale — the image is 4.1% darker ..."
  std::string line() const;
};

// Diagnoses a render that failed its comparison; `comparison` supplies the hard failures.
Diagnosis diagnoseDifference(const DiagnosisInput& input, const Comparison& comparison,
                             const ComparisonSettings& settings);

}  // namespace pathway
