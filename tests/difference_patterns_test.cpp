// The masks a grading reference stores for the diagnosis, made from a real scene: where there is a
// background, bounce rays that leave the scene return it at every depth, so the one-bounce mask
// holds its light after one bounce, and taking pattern.skyLitOnce out of it leaves the light that
// comes straight from the emitters: what the same mask gives with the background black.
#include "grade/difference_patterns.h"

#include <gtest/gtest.h>

#include "engine/render_session.h"
#include "grade/difference_diagnosis.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

// The image's sum over pixels and channels.
double total(const Image& image) {
  double sum = 0.0;
  for (const Color& c : image.pixels) sum += c.x + c.y + c.z;
  return sum;
}

std::map<std::string, Image> patternsOf(const GradingCase& gradingCase, const Scene& scene) {
  const RayTracer tracer(scene);
  const Image mean =
      runRender(tracer, gradingCase.recipe(Variant::Reference, EarlierStages::Own, 7)).images.color;
  return makeDifferencePatterns(gradingCase, tracer, mean, Image(), ReferenceTracing::Fastest);
}

TEST(DifferencePatterns, TheBackgroundsLightAfterOneBounceIsTakenOutOfTheOneBounceMask) {
  // Stage 4 in the open room (depth 1, three branches), small and at few samples.
  GradingCase gradingCase = findGradingCase("stage4-lights");
  gradingCase.width = gradingCase.height = 32;
  gradingCase.spp = 4;
  const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/" + gradingCase.scene);
  ASSERT_GT(maxComponent(scene.background), 0.0f) << "the test needs a scene with a background";
  const std::map<std::string, Image> patterns = patternsOf(gradingCase, scene);
  ASSERT_TRUE(patterns.count(pattern::kDirect) && patterns.count(pattern::kSkyLitOnce) &&
              patterns.count(pattern::kSkyLit) && patterns.count(pattern::kEscaped));
  const double oneBounce = total(patterns.at(pattern::kDirect));
  const double skyOnce = total(patterns.at(pattern::kSkyLitOnce));
  // At depth 1 the background's light on surfaces has had one bounce only.
  EXPECT_NEAR(total(patterns.at(pattern::kSkyLit)), skyOnce, 0.05 * skyOnce);

  Scene black = scene;
  black.background = Color(0.0f);
  const std::map<std::string, Image> withoutBackground = patternsOf(gradingCase, black);
  EXPECT_FALSE(withoutBackground.count(pattern::kSkyLitOnce));
  EXPECT_FALSE(withoutBackground.count(pattern::kEscaped));
  const double fromEmitters = total(withoutBackground.at(pattern::kDirect));
  // The background's share is large enough here for the test to fail if it were not taken out
  // (or taken out twice); the renders differ by their noise, a few per cent of the sums.
  ASSERT_GT(skyOnce, 0.2 * fromEmitters);
  EXPECT_NEAR(oneBounce - skyOnce, fromEmitters, 0.05 * fromEmitters);
}

}  // namespace
}  // namespace pathway
