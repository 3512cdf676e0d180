#include "grade/file_comparison.h"

#include <filesystem>
#include <utility>

#include "core/error.h"
#include "grade/reference_comparison.h"
#include "grade/stage_grading.h"

namespace pathway {

GradeSummary compareImageFiles(const std::string& image, const std::string& reference,
                               const ComparisonSettings& settings) {
  namespace fs = std::filesystem;
  GradeSummary summary;
  summary.title = "Pathway: " + image + " against " + reference;
  CaseResult result;
  result.id = "comparison";
  result.title =
      fs::path(image).filename().string() + " vs " + fs::path(reference).filename().string();
  result.purpose = "two files";
  result.maxPoints = 1.0;
  try {
    const LoadedImage render = readImageFile(image);
    LoadedImage other = readImageFile(reference);
    if (other.metadata.grading) {
      judgeAgainstReference(result, render, gradingReferenceOf(std::move(other), reference),
                            settings);
    } else {
      // A plain render as the reference: each file's own per-pixel variance.
      result.comparison = compareWithReference(render.images, render.metadata,
                                               {other.images, other.metadata}, settings);
      result.compared = true;
      result.passed = result.comparison.passed(settings);
      result.image = render.images.color;
      result.reference = other.images.color;
    }
  } catch (const PathwayError& error) {
    result.problem = error.what();
  }
  result.points = result.passed ? 1.0 : 0.0;
  summary.cases.push_back(std::move(result));
  return summary;
}

}  // namespace pathway
