// The course's own grading cases: one more per stage, at sizes, filters and settings of their own
// (every term of the stage's estimator still shows in them). The handout ships neither this file
// nor their references (scenes/references/course/), so a stage that copies the shipped references
// or bakes them into its source fails here; the autograder, which has both, grades them.
// scripts/make-handout leaves this file out and tells the handout how many there are.
#include "grade/grading_case_builder.h"

namespace pathway {
namespace {

std::vector<GradingCase> declareCourseCases() {
  using B = CaseBuilder;
  const B cases[] = {
      B(1, "course-edges-tent-wide", "grading_edges.gltf",
        "a tent of another radius at another size: the splat and its weights")
          .filter(FilterType::Tent, 1.5f)
          .size(80, 60)
          .spp(16)
          .tiles(2),
      B(2, "course-corner", "corner.gltf", "nested AO in a corner, three AO rays per hit")
          .param("ao-rays", "3")
          .param("ao-distance", "0.8")
          .size(72, 72)
          .spp(8),
      B(3, "course-ceiling", "ceiling.gltf", "4D AO under a ceiling: (h/r)^2 at another reach")
          .param("ao-distance", "1.6")
          .sobol()
          .size(72, 56)
          .spp(16),
      B(4, "course-cornell-box", "cornell_box.gltf", "three branches, one bounce, another size")
          .param("branching", "3")
          .param("depth", "1")
          .size(80, 80)
          .spp(8),
      B(5, "course-lights-deep", "grading_lights.gltf",
        "deeper paths, roulette from the first bounce, a tent filter")
          .param("max-depth", "6")
          .param("rr-depth", "1")
          .filter(FilterType::Tent)
          .size(88, 66)
          .spp(32),
  };
  std::vector<GradingCase> result;
  for (const B& b : cases) result.push_back(b.c);
  return result;
}

const bool registered = addCourseCases(declareCourseCases());

}  // namespace
}  // namespace pathway
