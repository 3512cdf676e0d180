// The warp test (grade/warp_fit.h): Pearson's statistic with pooling, checked by hand, and the
// verdict on warps that are right, wrong one way or the other, not a density, or off the
// hemisphere.
#include "grade/warp_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "grade/warp_picture.h"
#include "mutant_list.h"
#include "render/stage_kit.h"
#include "stage_loading/stage_library.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

constexpr float kPi = 3.14159265358979f;

Vec3 cosineDirection(Vec2 u) {  // cos θ = √(1 − u₁): a point of the disk at radius √u₁, lifted
  const float cosTheta = std::sqrt(1.0f - u.x), sinTheta = std::sqrt(u.x);
  const float azimuth = 2.0f * kPi * u.y;
  return {sinTheta * std::cos(azimuth), sinTheta * std::sin(azimuth), cosTheta};
}
Vec3 uniformDirection(Vec2 u) {  // cos θ uniform in [0, 1)
  const float z = u.x, r = std::sqrt(std::fmax(0.0f, 1.0f - z * z)), phi = 2.0f * kPi * u.y;
  return {r * std::cos(phi), r * std::sin(phi), z};
}
float cosinePdf(float cosTheta) {
  return cosTheta / kPi;
}
float uniformPdf(float) {
  return 1.0f / (2.0f * kPi);
}

TEST(PooledChiSquared, MatchesHandWorkedCounts) {
  int degrees = 0;
  // Cells expecting 3 and 3 pool into one expecting 6 (observed 3): 25/15 + 25/15 + 0 + 9/6.
  EXPECT_NEAR(pooledChiSquared({10, 20, 30, 2, 1}, {15, 15, 30, 3, 3}, degrees),
              25.0 / 15 + 25.0 / 15 + 9.0 / 6, 1e-12);
  EXPECT_EQ(degrees, 3);
  // A pool expecting 2 cannot stand alone: it joins the cell expecting least, (9, 10) -> (11, 11).
  EXPECT_NEAR(pooledChiSquared({10, 12, 1}, {9, 9, 2}, degrees), 9.0 / 9, 1e-12);
  EXPECT_EQ(degrees, 1);
}

TEST(WarpFit, ACosineWarpWithItsPdfPasses) {
  const WarpTestResult r = testHemisphereWarp({cosineDirection, cosinePdf}, {});
  EXPECT_TRUE(r.passed) << r.verdict;
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-6);
  EXPECT_NEAR(r.expectedMeanCosTheta, 2.0 / 3.0, 1e-6);  // ∫ cos² θ / π dω = 2/3
  EXPECT_EQ(r.invalid, 0);
}

TEST(WarpFit, APdfThatStepsToZeroAtTheHorizonIntegratesToOne) {
  // 1/(2π) above the horizon and 0 at cos θ = 0 (a right pdf): a rule that evaluated the ends
  // would lose part of the first panel.
  const auto steppingPdf = [](float c) { return c > 0.0f ? 1.0f / (2.0f * kPi) : 0.0f; };
  const WarpTestResult r = testHemisphereWarp({uniformDirection, steppingPdf}, {});
  EXPECT_NEAR(r.pdfIntegral, 1.0, 1e-6);
  EXPECT_TRUE(r.passed) << r.verdict;
}

TEST(WarpFit, SaysWhichWayTheDirectionsAreOff) {
  // Uniform directions under a cosine pdf: too many near the horizon.
  const WarpTestResult horizon = testHemisphereWarp({uniformDirection, cosinePdf}, {});
  EXPECT_FALSE(horizon.passed);
  EXPECT_NE(horizon.verdict.find("towards the horizon"), std::string::npos) << horizon.verdict;
  // Cosine directions under a uniform pdf: too many near the pole.
  const WarpTestResult pole = testHemisphereWarp({cosineDirection, uniformPdf}, {});
  EXPECT_FALSE(pole.passed);
  EXPECT_NE(pole.verdict.find("towards the pole"), std::string::npos) << pole.verdict;
}

TEST(WarpFit, APdfThatIsNotADensityFails) {
  const WarpTestResult r =
      testHemisphereWarp({cosineDirection, [](float c) { return c / (2.0f * kPi); }}, {});
  EXPECT_FALSE(r.passed);
  EXPECT_NEAR(r.pdfIntegral, 0.5, 1e-6);
  EXPECT_NE(r.verdict.find("integrates to 0.5"), std::string::npos) << r.verdict;
}

TEST(WarpFit, DirectionsBelowTheSurfaceFail) {
  WarpTestSettings settings;
  settings.samples = 5000;
  const WarpTestResult r =
      testHemisphereWarp({[](Vec2 u) { return -cosineDirection(u); }, cosinePdf}, settings);
  EXPECT_FALSE(r.passed);
  EXPECT_EQ(r.invalid, 5000);
  EXPECT_NE(r.verdict.find("5000 of 5000"), std::string::npos) << r.verdict;
}

TEST(WarpFit, DirectionsOnHalfTheCircleFailWithoutATilt) {
  // φ = π·u₂: the right cos θ, half the azimuths. Nothing crowds up or down; the cells say it.
  const WarpTestResult r = testHemisphereWarp(
      {[](Vec2 u) { return cosineDirection(Vec2(u.x, 0.5f * u.y)); }, cosinePdf}, {});
  EXPECT_FALSE(r.passed);
  EXPECT_NE(r.verdict.find("lean neither towards the pole nor the horizon"), std::string::npos)
      << r.verdict;
}

size_t occurrences(const std::string& text, const std::string& part) {
  size_t count = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++count;
  return count;
}

TEST(WarpPicture, ColoursEachCellByItsCountAndItsDifference) {
  WarpTestResult r;
  r.cosThetaCells = 1;
  r.phiCells = 2;
  r.observed = {140, 60};
  r.expected = {100, 100};  // (O − E)/√E = +4 and −4: full red and full blue
  r.directions = {Vec3(0, 0, 1)};
  r.verdict = "a < b & c";
  const std::string svg = warpTestSvg(r, "title");
  EXPECT_EQ(occurrences(svg, "fill='#ff0000'"), 1u) << svg;
  EXPECT_EQ(occurrences(svg, "fill='#0000ff'"), 1u);
  EXPECT_EQ(occurrences(svg, "fill='#fce824'"), 1u);  // the largest count, the top of the scale
  EXPECT_EQ(occurrences(svg, "r='0.9'"), 1u);         // one direction drawn
  // The background, then three panels of two cells and a frame each.
  EXPECT_EQ(occurrences(svg, "<rect"), 1u + 3u * 3u);
  EXPECT_NE(svg.find("a &lt; b &amp; c"), std::string::npos);
}

TEST(WarpPicture, WritesOnlyAnSvgFile) {
  const WarpTestResult r = testHemisphereWarp({cosineDirection, cosinePdf}, {});
  const std::string folder = ::testing::TempDir();
  EXPECT_THROW(writeWarpTestSvg(folder + "/warp.png", r, "title"), PathwayError);
  // A folder that is not there: one message, naming the file asked for.
  try {
    writeWarpTestSvg(folder + "/no such folder/warp.svg", r, "title");
    ADD_FAILURE() << "no error for a missing folder";
  } catch (const PathwayError& error) {
    EXPECT_EQ(std::string(error.what()).rfind(folder + "/no such folder/warp.svg: ", 0), 0u)
        << error.what();
  }
  writeWarpTestSvg(folder + "/warp.svg", r, "title");
  EXPECT_GT(std::filesystem::file_size(folder + "/warp.svg"), 1000u);
}

TEST(WarpFit, TheReferenceStage2Passes) {
  PATHWAY_REQUIRE_REFERENCE();
  const StageKit kit(2, Variant::Reference, EarlierStages::Own);
  const Stage2Functions& stage2 = kit.stage2();
  const WarpTestResult r =
      testHemisphereWarp({stage2.sampleCosineHemisphere, stage2.cosineHemispherePdf}, {});
  EXPECT_TRUE(r.passed) << r.verdict;
}

#ifdef PATHWAY_MUTANT_LIST
// The suite's stage-2 bugs in sampleCosineHemisphere or cosineHemispherePdf that make the two
// disagree: the warp test must fail exactly these, and pass every other stage-2 mutant (bugs
// elsewhere in the stage, or a routine changed but still consistent, such as uniform directions
// with their own pdf).
const char* const kWarpBugs[] = {"s2_uniform_pdf", "s2_uniform_directions", "s2_pdf_three_percent",
                                 "s2_pdf_one_percent"};

TEST(WarpFitMutants, TheListedRoutineBugsAreInTheSuite) {
  for (const char* name : kWarpBugs) {
    bool found = false;
    for (const test::Mutant& mutant : test::mutantsOfStage(2)) found = found || mutant.name == name;
    EXPECT_TRUE(found) << name << " is not a stage-2 mutant of " << PATHWAY_MUTANT_LIST;
  }
}

class WarpFitMutant : public ::testing::TestWithParam<test::Mutant> {};

TEST_P(WarpFitMutant, FailsExactlyWhenItsRoutineDisagreesWithItsPdf) {
  const test::Mutant& mutant = GetParam();
  bool isWarpBug = false;
  for (const char* name : kWarpBugs) isWarpBug = isWarpBug || mutant.name == name;
  // In a child process: a loaded library stays loaded, and its stage 2 replaces this one's.
  EXPECT_EXIT(
      {
        loadStageLibrary(mutant.library);
        const StageKit kit(2, Variant::Student, EarlierStages::Own);
        const Stage2Functions& stage2 = kit.stage2();
        const WarpTestResult r =
            testHemisphereWarp({stage2.sampleCosineHemisphere, stage2.cosineHemispherePdf}, {});
        std::fprintf(stderr, "%s\n", r.verdict.c_str());
        std::_Exit(r.passed ? 0 : 1);
      },
      ::testing::ExitedWithCode(isWarpBug ? 1 : 0), "");
}

INSTANTIATE_TEST_SUITE_P(Stage2, WarpFitMutant, ::testing::ValuesIn(test::mutantsOfStage(2)),
                         [](const ::testing::TestParamInfo<test::Mutant>& info) {
                           return info.param.name;
                         });
#endif  // PATHWAY_MUTANT_LIST

}  // namespace
}  // namespace pathway
