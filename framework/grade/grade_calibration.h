// How far the grader's verdicts can be trusted, measured: a stage is rendered with many fresh
// seeds and each render graded against the case's reference. Grading the reference stage this way
// gives the false-alarm rate; grading a stage with a planted bug (a mutant, loaded as a stage
// library) gives the detection rate. At another spp than the case's, the reference is made in
// memory first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "grade/grading_cases.h"
#include "grade/image_comparison.h"

namespace pathway {

struct CalibrationResult {
  std::string caseId;
  uint32_t spp = 0;
  int seeds = 0;
  int failures = 0;          // renders the grader failed
  double largestWorstP = 0;  // over the failed renders: how close the closest call came
  // Over all renders: the one closest to the reference (Comparison::closeness; an exact image
  // scores about 1), and the chance of an exact image coming that close (the too-close test).
  double smallestCloseness = -1.0;
  double smallestClosenessP = 1.0;
  // Over all renders: the noise ratio's range (Comparison::noiseRatio; 0 where not measured) and
  // how many renders were too noisy for the case's required technique (Comparison::tooNoisy).
  double smallestNoiseRatio = 0.0;
  double largestNoiseRatio = 0.0;
  int tooNoisy = 0;
  std::vector<uint64_t> failedSeeds;  // to look at a failure again: pathway grade --seed S
  // ... of them, those whose confirmation render (another seed) failed too: the verdicts
  std::vector<uint64_t> verdictSeeds;
  double seconds = 0.0;  // rendering and grading, references excluded
};

// Grades `variant`'s stage (the reference traced as `tracing` says) (the student's: a loaded stage
// library) on `gradingCase` at `spp` with seeds firstSeed, firstSeed + 1, ... The reference comes
// from `referencesFolder` when `spp` is the case's own, else it is rendered first.
CalibrationResult calibrate(const GradingCase& gradingCase, uint32_t spp, Variant variant,
                            ReferenceTracing tracing, int seeds, uint64_t firstSeed,
                            const std::string& referencesFolder, const std::string& scenesFolder,
                            const ComparisonSettings& settings);

}  // namespace pathway
