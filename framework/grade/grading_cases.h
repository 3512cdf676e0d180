// The course's grading cases: for each stage, a few scenes and settings picked so that the
// stage's typical bugs change the image somewhere, with the sample count a submission renders at.
// The references are made from solutions/ at kReferenceReplicates times that sample count
// (`pathway grade --make-references`) and shipped with the handout. Beside them, the course keeps
// cases of its own (framework/grade/course_cases.cpp, built in where it exists): the handout has
// neither their definitions nor their references, so a stage that copies or bakes in the shipped
// references fails them; the autograder grades them, a handout's self-grade cannot.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "core/variant.h"
#include "engine/render_session.h"
#include "film/pixel_filter.h"
#include "render/integrator_registry.h"

namespace pathway {

// Independent renders that make up a reference: their mean is the reference image (at
// kReferenceReplicates times the student's spp), their spread the variance of one student render.
constexpr int kReferenceReplicates = 64;
// Seeds: a submission renders with kStudentSeed, reference replicate i with kReferenceSeed + i
// (engine/render_settings.h).
constexpr uint64_t kStudentSeed = 1;

struct GradingCase {
  int stage = 1;
  std::string name;                           // unique within the stage: "cornell-tent"
  std::string scene;                          // file name under scenes/
  std::map<std::string, std::string> params;  // as on the command line; the rest at defaults
  FilterType filter = FilterType::Box;
  float filterRadius = 0.0f;  // 0: natural
  bool sobol = false;         // else the stage's own default sampler
  int width = 96, height = 96;
  uint32_t spp = 16;  // what a submission renders at
  // Pixels per side of a tested tile: small where the bugs to catch move light only a pixel or
  // two (a filter's shape barely changes an 8x8 tile's mean), large where samples are rare
  // events that need many per tile.
  int tileSize = 8;
  std::string purpose;  // one line: what it is there to catch
  // A technique the stage's README requires that changes the noise, not the expectation (stage
  // 5's light sampling, stage 2's M rays per hit): a render more than noiseBound times as noisy
  // as the reference's here (both by the jackknife) left it out and fails, with
  // requiredTechnique as the reason. 0: no bound. The bounds are calibrated: every valid method
  // stays 10 times below (docs/grading-course.md).
  double noiseBound = 0.0;
  std::string requiredTechnique;
  bool courseOnly = false;  // kept by the course: not in a handout (course_cases.cpp)

  // Whether a valid submission may be noisier than the reference here, so that its render carries
  // its own variance (grade/jackknife_render.h): from stage 2 on, where the student picks
  // directions and their pdf. Stage 1's estimator is the framework's samples through the filter,
  // so a valid splat is exactly as noisy as the reference's, and noise excuses nothing there (a
  // box where Mitchell belongs is noisier on edges too).
  bool ownNoiseCounts() const { return stage >= 2; }

  std::string id() const { return "stage" + std::to_string(stage) + "-" + name; }
  // The reference file's name under the references folder (course cases: in its course/).
  std::string referenceFile() const {
    return (courseOnly ? std::string(kCourseReferenceFolder) + "/" : "") + id() + ".exr";
  }
  static constexpr const char* kCourseReferenceFolder = "course";
  // The recipe for this case: the stage in `variant`, earlier stages from `earlier`. The
  // reference stage renders with its wavefront version where it has one, unless `tracing` is
  // SingleRay (render/integrator_registry.h).
  RenderRecipe recipe(Variant variant, EarlierStages earlier, uint64_t seed,
                      ReferenceTracing tracing = ReferenceTracing::Fastest) const;
};

// Every case: the shipped ones, then the course's own where they are built in.
const std::vector<GradingCase>& gradingCases();
// Adds the course's own cases (marked courseOnly); course_cases.cpp calls it while the program
// starts, before anything asks for the cases.
bool addCourseCases(std::vector<GradingCase> cases);
// A line for people about the course's cases this program does not have: read from
// `referencesFolder`/course-cases.txt, which scripts/make-handout writes into a handout ("" when
// there is none, or when the cases are built in).
std::string courseCasesNotHere(const std::string& referencesFolder);
// The cases of one stage; throws PathwayError for a stage that has none.
std::vector<const GradingCase*> gradingCasesOf(int stage);
// Throws PathwayError naming the known ids.
const GradingCase& findGradingCase(const std::string& id);
// The same, or nullptr (a course case's reference read where its definition is not built in).
const GradingCase* gradingCaseOrNull(const std::string& id);

}  // namespace pathway
