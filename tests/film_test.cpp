// The film and stage 1's splat: analytic weights, and numerical normalisation that makes a constant
// scene come back exactly constant for every filter, also where Σw is close to zero.
#include "film/film.h"

#include <gtest/gtest.h>

#include <cmath>

#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "film/pixel_filter.h"
#include "render/stage_kit.h"
#include "sampling/pcg32.h"
#include "stage_under_test.h"
#include "test_scenes.h"

namespace pathway {
namespace {

TEST(Film, SplatAddsTheFilterWeightToEveryPixelInReach) {
  PATHWAY_REQUIRE_REFERENCE();
  const Stage1Functions& stage1 = test::stage1UnderTest();
  for (FilterType type :
       {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali, FilterType::Gaussian}) {
    const PixelFilter filter(type, naturalFilterRadius(type), stage1.profiles);
    FilmBlock block(16, 16, 0, 0, 16, 16);
    const Vec2 p(7.3f, 8.9f);
    const Color radiance(2.0f, 3.0f, 4.0f);
    stage1.splat(block, p, radiance, filter);
    for (int y = 0; y < 16; ++y) {
      for (int x = 0; x < 16; ++x) {
        const float expected = filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f));
        const PixelSums& sums = block.at(x, y);
        EXPECT_FLOAT_EQ(static_cast<float>(sums.weight), expected)
            << filterTypeName(type) << " pixel " << x << "," << y;
        EXPECT_FLOAT_EQ(static_cast<float>(sums.weightedRadiance.y), expected * radiance.y);
      }
    }
  }
}

// The reference's splat, which every reference render calls, takes each row's and column's weight
// once (solutions/stage1): its sums must be those of the splat as the stage README defines it,
// bit for bit, or the references would change with it.
TEST(Film, ReferenceSplatAddsExactlyTheDefinitionsSums) {
  PATHWAY_REQUIRE_REFERENCE();
  const StageKit kit(1, Variant::Reference, EarlierStages::Own);
  const Stage1Functions& reference = kit.stage1();
  // The definition: every pixel of the block, row by row, gets f(dx)·f(dy) where that is not 0
  // (the filter is 0 beyond its radius).
  auto definition = [](FilmBlock& block, Vec2 p, const Color& radiance, const PixelFilter& f) {
    for (int y = block.y0(); y < block.y0() + block.height(); ++y)
      for (int x = block.x0(); x < block.x0() + block.width(); ++x)
        if (const float w = f.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f)); w != 0.0f)
          block.addSample(x, y, w, radiance);
  };
  Pcg32 random(45);
  for (FilterType type :
       {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali, FilterType::Gaussian}) {
    // The natural radius, others, and one wider than the fast splat's window (it hands over).
    for (float radius : {naturalFilterRadius(type), 0.3f, 1.7f, 7.4f, 8.0f}) {
      const PixelFilter filter(type, radius, reference.profiles);
      FilmBlock fast(24, 24, 4, 2, 16, 16), plain(24, 24, 4, 2, 16, 16);
      for (int i = 0; i < 400; ++i) {
        // Over the block and a margin round it, where pixels out of the block are skipped.
        const Vec2 p(random.nextFloat() * 30.0f - 3.0f, random.nextFloat() * 30.0f - 3.0f);
        const Color radiance(random.nextFloat(), random.nextFloat() * 2.0f, 0.5f);
        reference.splat(fast, p, radiance, filter);
        definition(plain, p, radiance, filter);
      }
      for (int y = 2; y < 18; ++y)
        for (int x = 4; x < 20; ++x) {
          const PixelSums &a = fast.at(x, y), &b = plain.at(x, y);
          ASSERT_TRUE(a.weightedRadiance == b.weightedRadiance && a.weight == b.weight &&
                      a.absWeight == b.absWeight &&
                      a.squaredWeightRadiance == b.squaredWeightRadiance &&
                      a.squaredWeightRadiance2 == b.squaredWeightRadiance2 &&
                      a.squaredWeight == b.squaredWeight && a.sampleCount == b.sampleCount)
              << filterTypeName(type) << " radius " << radius << " pixel " << x << "," << y;
        }
    }
  }
}

TEST(Film, DevelopDividesWeightedRadianceByWeight) {
  Film film(2, 1);
  FilmBlock block(2, 1, 0, 0, 2, 1);
  block.addSample(0, 0, 0.5f, Color(2.0f));
  block.addSample(0, 0, 1.5f, Color(4.0f));
  block.addSample(1, 0, 1.0f, Color(1.0f));
  block.addSample(1, 0, -1.0f, Color(3.0f));  // Σw = 0 exactly: unresolved, written as 0
  block.addSample(5, 5, 1.0f, Color(9.0f));   // outside the image: ignored
  film.merge(block);
  size_t unresolved = 0;
  const Image image = film.develop(&unresolved);
  EXPECT_FLOAT_EQ(image.at(0, 0).x, (0.5f * 2 + 1.5f * 4) / 2.0f);
  EXPECT_EQ(image.at(1, 0), Color(0.0f));
  EXPECT_EQ(unresolved, 1u);
  // Variance of the ratio estimate, I = 3.5: Σ w²(L - I)² / (Σw)² = (0.25·1.5² + 2.25·0.5²) / 4.
  EXPECT_NEAR(film.variance().at(0, 0).x, (0.25 * 1.5 * 1.5 + 2.25 * 0.5 * 0.5) / 4.0, 1e-6);
}

// Renders a scene whose radiance is the same everywhere; the developed image must be that value.
TEST(Film, ConstantSceneComesBackExactlyForEveryFilterAndSampleCount) {
  PATHWAY_REQUIRE_REFERENCE();
  const Color constant(0.3f, 0.7f, 1.9f);
  const Scene scene = test::constantScene(constant);
  const RayTracer tracer(scene);
  for (FilterType type :
       {FilterType::Box, FilterType::Tent, FilterType::MitchellNetravali, FilterType::Gaussian}) {
    for (uint32_t spp : {1u, 2u, 4u}) {
      const RenderRecipe recipe =
          RecipeBuilder(test::stage(1)).size(48, 32).spp(spp, 1).filter(type).seed(7);
      const RenderResult result = runRender(tracer, recipe);
      size_t zeroPixels = 0;
      for (const Color& pixel : result.images.color.pixels) {
        ASSERT_TRUE(isFinite(pixel));
        if (pixel == Color(0.0f)) {
          ++zeroPixels;  // only where Σw ≈ 0, which the film counts
          continue;
        }
        for (int c = 0; c < 3; ++c) ASSERT_FLOAT_EQ(pixel[c], constant[c]) << filterTypeName(type);
      }
      EXPECT_EQ(zeroPixels, result.unresolvedPixels) << filterTypeName(type) << " " << spp;
      if (type != FilterType::MitchellNetravali) {
        EXPECT_EQ(zeroPixels, 0u) << filterTypeName(type);
      }
      EXPECT_EQ(result.stats.counters.invalidSamples, 0u);
    }
  }
}

}  // namespace
}  // namespace pathway
