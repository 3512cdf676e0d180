#include "grade/file_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <utility>

#include "core/error.h"
#include "grade/reference_comparison.h"
#include "grade/stage_grading.h"

namespace pathway {
namespace {

// The plain facts beside the statistical test, for two files of one size: whether their pixels
// are the same bits (two builds of one renderer on two systems should give that), and if not,
// how many values differ, by how much at most, and how far apart the two means are.
std::string pixelDifference(const Image& image, const Image& reference) {
  if (image.width != reference.width || image.height != reference.height) return "";
  const size_t values = 3 * image.pixels.size();
  if (std::memcmp(image.pixels.data(), reference.pixels.data(), values * sizeof(float)) == 0)
    return "pixels: identical, bit for bit (" + std::to_string(values) + " values)";
  size_t differing = 0;
  double largest = 0.0, sumImage = 0.0, sumReference = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      const double a = image.pixels[i][c], b = reference.pixels[i][c];
      differing += a != b;
      largest = std::max(largest, std::abs(a - b));
      sumImage += a;
      sumReference += b;
    }
  std::ostringstream out;
  out.precision(3);
  out << "pixels: " << differing << " of " << values << " values differ, by at most " << largest
      << "; the means differ by "
      << (sumReference != 0.0 ? 100.0 * (sumImage / sumReference - 1.0) : 0.0) << "%";
  return out.str();
}

}  // namespace

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
    result.note = pixelDifference(render.images.color, other.images.color);
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
