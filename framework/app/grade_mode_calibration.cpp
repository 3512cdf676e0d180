// `pathway grade --calibrate SEEDS`: the false-alarm rate (the reference stages,
// --grade-reference) or the detection rate (a stage library) of each selected case over many
// seeds, graded in this process, as a table on stdout.
#include <cstdio>
#include <string>

#include "app/grade_modes.h"
#include "grade/grade_calibration.h"
#include "stage_loading/stage_library.h"
#include "stage_loading/student_stages.h"

namespace pathway {
namespace {

// "0.93-1.12": the smallest and largest of a measure over the seeds.
std::string formatRange(double smallest, double largest) {
  char text[40];
  std::snprintf(text, sizeof text, "%.3g-%.3g", smallest, largest);
  return text;
}

}  // namespace

int calibrateMode(const GradeOptions& options) {
  for (const std::string& library : options.stageLibraries) loadStageLibrary(library);
  // Calibrating the student's stages as this build made them (in this process, unsandboxed:
  // a tool for the course's own code, not for submissions).
  if (!options.gradeReference && options.stageLibraries.empty()) loadStudentStages();
  const Variant variant = options.gradeReference ? Variant::Reference : Variant::Student;
  const ComparisonSettings settings;
  std::printf("%-32s %5s %6s %9s %9s %9s %11s %10s %11s %17s %9s %8s\n", "case", "spp", "seeds",
              "failures", "rate", "verdicts", "closest p", "closeness", "its p", "noise ratio",
              "too noisy", "seconds");
  for (const GradingCase* c : selectedCases(options)) {
    std::vector<uint32_t> spps = options.calibrationSpp;
    if (spps.empty()) spps.push_back(c->spp);
    for (uint32_t spp : spps) {
      const CalibrationResult r =
          calibrate(*c, spp, variant, options.referenceTracing(), options.calibrate, options.seed,
                    options.references, kScenesDir, settings);
      std::string seeds;  // the first few, to look at again with --seed
      for (size_t i = 0; i < r.failedSeeds.size() && i < 5; ++i)
        seeds += (i ? "," : "  seeds ") + std::to_string(r.failedSeeds[i]);
      const std::string noise =
          r.largestNoiseRatio > 0.0 ? formatRange(r.smallestNoiseRatio, r.largestNoiseRatio) : "-";
      std::printf("%-32s %5u %6d %9d %9.4f %9d %11.3g %10.3g %11.3g %17s %9d %8.1f%s\n",
                  r.caseId.c_str(), r.spp, r.seeds, r.failures, double(r.failures) / r.seeds,
                  int(r.verdictSeeds.size()), r.largestWorstP, r.smallestCloseness,
                  r.smallestClosenessP, noise.c_str(), r.tooNoisy, r.seconds, seeds.c_str());
      if (options.verdictSeeds) {
        std::printf("verdict seeds:");
        for (uint64_t seed : r.verdictSeeds) std::printf(" %llu", (unsigned long long)seed);
        std::printf("\n");
      }
      std::fflush(stdout);
    }
  }
  return 0;
}

}  // namespace pathway
