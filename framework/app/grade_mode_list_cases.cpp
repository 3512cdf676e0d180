// `pathway grade --list-cases`: every grading case with its scene, settings and what it is there
// to catch, and the smallest bias its reference lets the grader see. Also what `pathway cluster
// grade` runs to check its grade options before submitting.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "app/grade_modes.h"
#include "core/number_format.h"
#include "grade/grading_reference.h"
#include "grade/image_comparison.h"

namespace pathway {

namespace {

// The smallest relative bias the case catches half the time ("-" without its reference here).
std::string smallestBias(const GradingCase& c, const std::string& references) {
  const std::string path = references + "/" + c.referenceFile();
  if (!std::filesystem::exists(path)) return "-";
  const GradingReference reference = readGradingReference(path);
  const double bias =
      smallestDetectableBias(reference.mean, reference.blockVariance, reference.record.blockSize,
                             reference.record.replicates, reference.record.blockCorrelation);
  return std::isfinite(bias) ? formatNumber("%.2f%%", 100.0 * bias) : "-";
}

}  // namespace

int listCasesMode(const GradeOptions& options) {
  std::printf("%-30s %-26s %-9s %4s %4s %7s %6s  %s\n", "case", "scene", "filter", "spp", "tile",
              "size", "bias", "parameters: what it is there to catch");
  for (const GradingCase& c : gradingCases()) {
    std::string params;
    for (const auto& [name, value] : c.params) params += name + "=" + value + " ";
    const std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
    const std::string noise =
        c.noiseBound > 0.0 ? formatNumber("(noise at most %gx the reference's) ", c.noiseBound)
                           : "";
    std::printf("%-30s %-26s %-9s %4u %4d %7s %6s  %s%s%s%s%s\n", c.id().c_str(), c.scene.c_str(),
                filterTypeName(c.filter).c_str(), c.spp, c.tileSize, size.c_str(),
                smallestBias(c, options.references).c_str(), params.c_str(),
                c.sobol ? "(sobol) " : "", c.courseOnly ? "(course only) " : "", noise.c_str(),
                c.purpose.c_str());
  }
  std::printf(
      "bias: the smallest relative bias the same everywhere (the image times 1 + b) that "
      "the whole-image test catches in half of the renders as noisy as the reference's "
      "(a bias in part of the image needs more); noise at most: a case that also fails a render "
      "that much noisier than the reference's (a technique the stage README requires)\n");
  return 0;
}

}  // namespace pathway
