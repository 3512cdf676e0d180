#include "viewer/frame_grade.h"

#include <algorithm>
#include <exception>
#include <sstream>

#include "core/error.h"
#include "grade/grade_report.h"
#include "render/render_session.h"

namespace pathway {
namespace {

constexpr uint32_t kMinimumSpp = 4;

}  // namespace

bool canGradeFrame(const LaneFrame& frame) {
  if (!frame.error.empty() || frame.images.color.pixels.empty()) return false;
  const IntegratorInfo* info = nullptr;
  for (const IntegratorInfo* candidate : allIntegrators())
    if (candidate->name == frame.integrator) info = candidate;
  return info && info->stage > 0 && findStageIntegrator(info->stage, Variant::Reference);
}

FrameGrade gradeFrame(const LaneFrame& frame, const LoadedScene& scene) {
  FrameGrade grade;
  grade.job = frame.job;
  grade.spp = frame.stats.samplesPerPixel;
  grade.integrator = frame.integrator;
  try {
    const IntegratorInfo& shown = findIntegrator(frame.integrator);
    const IntegratorInfo* reference = findStageIntegrator(shown.stage, Variant::Reference);
    if (shown.stage == 0 || !reference)
      throw PathwayError("no reference of " + frame.integrator + " is built into this program");
    if (frame.stats.samplesPerPixel < kMinimumSpp)
      throw PathwayError("grading needs at least " + std::to_string(kMinimumSpp) +
                         " samples per pixel (each pixel's own variance estimate)");
    grade.reference = reference->name;
    RenderRecipe recipe;
    recipe.integrator = reference->name;
    recipe.params = frame.params;  // the stage's parameters are declared once, for both
    recipe.settings = frame.settings;
    recipe.settings.samplesPerPixel = std::max(frame.stats.samplesPerPixel, 16u);
    recipe.settings.samplesPerPass = recipe.settings.samplesPerPixel;
    recipe.settings.seed = frame.settings.seed + 7919;  // independent of the shown image
    const CameraPose& pose = frame.camera;
    const Camera camera(pose.position, pose.lookAt, pose.up, pose.yfov, recipe.settings.width,
                        recipe.settings.height);
    // A session of its own, without runRender's clearing of the TODO log, which the render
    // worker is reading for the shown pane at the same time.
    RenderSession session(*scene.tracer, camera, recipe);
    session.renderer().renderAll();
    const RenderResult result = session.develop({});

    ComparisonInput input;
    input.image = &frame.images.color;
    input.imageVariance = &frame.images.variance;
    input.reference = &result.images.color;
    input.referenceVariance = &result.images.variance;
    input.negativeValuesAllowed = hasNegativeLobes(frame.settings.filter);
    input.pixelCorrelation = filterPixelCorrelation(frame.settings.filterRadiusPixels());
    input.droppedSamples = frame.stats.counters.invalidSamples;
    const ComparisonSettings settings;
    grade.comparison = compareImages(input, settings);
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
