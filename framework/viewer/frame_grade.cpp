#include "viewer/frame_grade.h"

#include <algorithm>
#include <exception>
#include <sstream>

#include "core/error.h"
#include "grade/grade_report.h"
#include "grade/reference_comparison.h"
#include "viewer/stage_reference.h"

namespace pathway {
namespace {

constexpr uint32_t kMinimumSpp = 4;

}  // namespace

bool canGradeFrame(const LaneFrame& frame) {
  return frame.error.empty() && !frame.images.color.pixels.empty() &&
         stageReferenceOf(frame.integrator);
}

FrameGrade gradeFrame(const LaneFrame& frame, const LoadedScene& scene) {
  FrameGrade grade;
  grade.job = frame.job;
  grade.spp = frame.stats.samplesPerPixel;
  grade.integrator = frame.integrator;
  try {
    const IntegratorInfo* reference = stageReferenceOf(frame.integrator);
    if (!reference) throw PathwayError(missingReferenceOf(frame.integrator));
    if (frame.stats.samplesPerPixel < kMinimumSpp)
      throw PathwayError("grading needs at least " + std::to_string(kMinimumSpp) +
                         " samples per pixel (each pixel's own variance estimate)");
    grade.reference = reference->name;
    const uint32_t spp = std::max(frame.stats.samplesPerPixel, 16u);
    const RenderResult result = *renderStageReference(frame, scene, spp, spp);

    const ComparisonSettings settings;
    grade.comparison = compareWithReference(frame.images, frame.metadata,
                                            {result.images, result.metadata}, settings);
    grade.passed = grade.comparison.passed(settings);
    if (!grade.comparison.tiles.empty()) grade.heatmap = zHeatmap(grade.comparison);
    std::ostringstream summary;
    summary << "at " << grade.spp << " spp, " << (grade.passed ? "matches " : "differs from ")
            << reference->name << " (" << result.stats.samplesPerPixel
            << " spp): " << grade.comparison.describe(settings);
    grade.summary = summary.str();
  } catch (const std::exception& error) {
    grade.error = error.what();
  }
  return grade;
}

}  // namespace pathway
