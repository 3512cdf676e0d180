// The warp test of stage 5's light sampling (grade/light_sampling_fit.h): hand-written samplers
// that are right, or wrong in one known way each, on the grading scene with three lights of
// different sizes and strengths (six triangles); the reference's routine; and the suite's
// stage-5 bugs, each failing exactly when it changes what sampleLight claims.
#include "grade/light_sampling_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

#include "mutant_list.h"
#include "render/stage_kit.h"
#include "scene/gltf_loader.h"
#include "stage_loading/stage_library.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

const Scene& lightsScene() {
  static const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/grading_lights.gltf");
  return scene;
}

// A point on the picked triangle from barycentrics (b0, b1), with the density `pdf` gives it.
template <typename Pdf>
LightSample pointOn(const EmitterPicker::Pick& pick, float b0, float b1, Pdf pdf) {
  const EmissiveTriangle& e = *pick.emitter;
  LightSample s;
  s.position = b0 * e.p0 + b1 * e.p1 + (1.0f - b0 - b1) * e.p2;
  s.normal = e.normal;
  s.emitter = &e;
  s.pdfArea = pdf(pick, e);
  return s;
}
float truePdf(const EmitterPicker::Pick& pick, const EmissiveTriangle& e) {
  return pick.probability / e.area;
}

LightSample uniformPoint(const EmitterPicker& lights, float uPick, Vec2 u) {
  const float s = std::sqrt(u.x);
  return pointOn(lights.pick(uPick), 1.0f - s, u.y * s, truePdf);
}

LightSamplingTestResult run(const LightSampler& sampler, EmitterWeighting weighting) {
  const EmitterPicker picker(lightsScene(), weighting);
  return testLightSampling(sampler, picker, collectEmissiveTriangles(lightsScene()), {});
}

TEST(LightSamplingFit, AUniformPointWithItsDensityPasses) {
  for (EmitterWeighting weighting : {EmitterWeighting::Area, EmitterWeighting::Power}) {
    const LightSamplingTestResult r = run(uniformPoint, weighting);
    EXPECT_TRUE(r.passed) << r.verdict;
    EXPECT_EQ(r.emitters, 6);
    EXPECT_NEAR(r.probabilitySum, 1.0, 1e-5);
    EXPECT_NEAR(r.meanWeightOfP0, 1.0 / 3.0, 0.002);
  }
}

TEST(LightSamplingFit, PointsWithoutTheSquareRootCrowdTowardsTheFirstCorner) {
  // s = u₁: the mean weight of p0 is E[1 − u₁] = 1/2 instead of 1/3.
  const LightSamplingTestResult r =
      run([](const EmitterPicker& lights, float uPick,
             Vec2 u) { return pointOn(lights.pick(uPick), 1.0f - u.x, u.y * u.x, truePdf); },
          EmitterWeighting::Power);
  EXPECT_FALSE(r.passed);
  EXPECT_NEAR(r.meanWeightOfP0, 0.5, 0.002);
  EXPECT_NE(r.verdict.find("crowd towards each triangle's first corner"), std::string::npos)
      << r.verdict;
}

TEST(LightSamplingFit, ADensityWithoutThePickProbabilityFails) {
  const LightSamplingTestResult r = run(
      [](const EmitterPicker& lights, float uPick, Vec2 u) {
        const float s = std::sqrt(u.x);
        return pointOn(
            lights.pick(uPick), 1.0f - s, u.y * s,
            [](const EmitterPicker::Pick&, const EmissiveTriangle& e) { return 1.0f / e.area; });
      },
      EmitterWeighting::Area);
  EXPECT_FALSE(r.passed);
  EXPECT_NEAR(r.probabilitySum, 6.0, 1e-4);  // six triangles, each claiming probability 1
  EXPECT_NE(r.verdict.find("summed over the emitters, is 6"), std::string::npos) << r.verdict;
}

TEST(LightSamplingFit, APickWhoseProbabilityIsAnotherPicksFails) {
  // Picked by power, the density claims the area pick's probability: the sum is still 1, but the
  // emitters are chosen at other rates than claimed.
  const EmitterPicker byArea(lightsScene(), EmitterWeighting::Area);
  std::map<std::pair<uint32_t, uint32_t>, float> areaProbability;  // by mesh and triangle
  for (float v = 0.0f; v < 1.0f; v += 1.0f / 4096) {
    const EmitterPicker::Pick pick = byArea.pick(v);
    areaProbability[{pick.emitter->mesh, pick.emitter->triangle}] = pick.probability;
  }
  ASSERT_EQ(areaProbability.size(), 6u);
  const LightSamplingTestResult r = run(
      [&](const EmitterPicker& lights, float uPick, Vec2 u) {
        const float s = std::sqrt(u.x);
        return pointOn(lights.pick(uPick), 1.0f - s, u.y * s,
                       [&](const EmitterPicker::Pick&, const EmissiveTriangle& e) {
                         return areaProbability.at({e.mesh, e.triangle}) / e.area;
                       });
      },
      EmitterWeighting::Power);
  EXPECT_FALSE(r.passed);
  EXPECT_NEAR(r.probabilitySum, 1.0, 1e-3);
  EXPECT_LT(r.pickP, 1e-10);
  EXPECT_NE(r.verdict.find("is chosen"), std::string::npos) << r.verdict;
}

TEST(LightSamplingFit, PointsOffTheTriangleFail) {
  const LightSamplingTestResult r = run(
      [](const EmitterPicker& lights, float uPick, Vec2 u) {
        LightSample s = uniformPoint(lights, uPick, u);
        s.position += 0.01f * s.normal;  // pushed off the light
        return s;
      },
      EmitterWeighting::Area);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.invalid, 200000);
  EXPECT_NE(r.verdict.find("not on the triangle"), std::string::npos) << r.verdict;
}

TEST(LightSamplingFit, TheReferenceStage5Passes) {
  PATHWAY_REQUIRE_REFERENCE();
  const Stage5Functions& stage5 = stage5Functions(Variant::Reference);
  for (EmitterWeighting weighting : {EmitterWeighting::Area, EmitterWeighting::Power}) {
    const LightSamplingTestResult r = run(stage5.sampleLight, weighting);
    EXPECT_TRUE(r.passed) << r.verdict;
  }
}

#ifdef PATHWAY_MUTANT_LIST
// The suite's stage-5 bugs in sampleLight that make its points and their density disagree: the
// warp test must fail exactly these, and pass every other stage-5 mutant.
const char* const kLightSamplingBugs[] = {"s5_area_pdf_five_percent", "s5_area_pdf_two_percent",
                                          "s5_pdf_by_area_picked_by_power"};

TEST(LightSamplingFitMutants, TheListedRoutineBugsAreInTheSuite) {
  for (const char* name : kLightSamplingBugs) {
    bool found = false;
    for (const test::Mutant& mutant : test::mutantsOfStage(5)) found = found || mutant.name == name;
    EXPECT_TRUE(found) << name << " is not a stage-5 mutant of " << PATHWAY_MUTANT_LIST;
  }
}

class LightSamplingFitMutant : public ::testing::TestWithParam<test::Mutant> {};

TEST_P(LightSamplingFitMutant, FailsExactlyWhenItsPointsDisagreeWithTheirDensity) {
  const test::Mutant& mutant = GetParam();
  bool isSamplingBug = false;
  for (const char* name : kLightSamplingBugs) isSamplingBug = isSamplingBug || mutant.name == name;
  // In a child process: a loaded library stays loaded, and its stage 5 replaces this one's.
  EXPECT_EXIT(
      {
        loadStageLibrary(mutant.library);
        bool passed = true;
        for (EmitterWeighting weighting : {EmitterWeighting::Area, EmitterWeighting::Power}) {
          const LightSamplingTestResult r =
              run(stage5Functions(Variant::Student).sampleLight, weighting);
          std::fprintf(stderr, "%s\n", r.verdict.c_str());
          passed = passed && r.passed;
        }
        std::_Exit(passed ? 0 : 1);
      },
      ::testing::ExitedWithCode(isSamplingBug ? 1 : 0), "");
}

INSTANTIATE_TEST_SUITE_P(Stage5, LightSamplingFitMutant,
                         ::testing::ValuesIn(test::mutantsOfStage(5)),
                         [](const ::testing::TestParamInfo<test::Mutant>& info) {
                           return info.param.name;
                         });
#endif  // PATHWAY_MUTANT_LIST

}  // namespace
}  // namespace pathway
