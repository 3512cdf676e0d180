// The renderer: same seed -> bit-identical image for any thread count; exact counters; cancel.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <future>
#include <numeric>
#include <thread>

#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "scene/gltf_loader.h"
#include "stage_under_test.h"
#include "test_scenes.h"

namespace pathway {
namespace {

RenderRecipe smallRecipe(int threads, SamplerType sampler) {
  return RecipeBuilder(test::stage(1))
      .size(70, 45)  // not a multiple of the tile size, on purpose
      .spp(4, 2)
      .filter(FilterType::MitchellNetravali)
      .sampler(sampler)
      .seed(11)
      .threads(threads);
}

// An integrator of the stage under test at its default parameters.
std::unique_ptr<Integrator> makeIntegrator(int stage, const Scene& scene,
                                           const std::map<std::string, std::string>& params = {}) {
  const IntegratorInfo& info = findIntegrator(test::stage(stage));
  const StageKit kit = info.kit();
  return info.create({resolveParams(info.name, info.params, params), kit, scene});
}

TEST(Renderer, SameSeedGivesBitIdenticalImagesForOneAndManyThreads) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  // As the viewer renders: with a cancel flag (never set), so the film is merged before every
  // pass instead of once at the end (runRender).
  auto renderCancellable = [&](const RenderRecipe& recipe) {
    const Camera camera(scene, recipe.settings.width, recipe.settings.height);
    RenderSession session(tracer, camera, recipe);
    const std::atomic<bool> never{false};
    session.renderer().renderAll({}, &never);
    return session.develop();
  };
  for (SamplerType sampler :
       {SamplerType::Independent, SamplerType::Stratified, SamplerType::Sobol}) {
    const RenderResult one = runRender(tracer, smallRecipe(1, sampler));
    const RenderResult oneCancellable = renderCancellable(smallRecipe(1, sampler));
    for (int threads : {2, 3, 8}) {
      const RenderResult manyCancellable = renderCancellable(smallRecipe(threads, sampler));
      EXPECT_EQ(0, std::memcmp(oneCancellable.images.color.pixels.data(),
                               manyCancellable.images.color.pixels.data(),
                               oneCancellable.images.color.pixels.size() * sizeof(Color)))
          << samplerTypeName(sampler) << " with " << threads << " threads, cancellable passes";
      const RenderResult many = runRender(tracer, smallRecipe(threads, sampler));
      ASSERT_EQ(one.images.color.pixels.size(), many.images.color.pixels.size());
      EXPECT_EQ(0, std::memcmp(one.images.color.pixels.data(), many.images.color.pixels.data(),
                               one.images.color.pixels.size() * sizeof(Color)))
          << samplerTypeName(sampler) << " with " << threads << " threads";
      EXPECT_EQ(0,
                std::memcmp(one.images.variance.pixels.data(), many.images.variance.pixels.data(),
                            one.images.variance.pixels.size() * sizeof(Color)));
    }
    // A different seed must change the image (otherwise the test above proves nothing).
    RenderRecipe other = smallRecipe(1, sampler);
    other.settings.seed = 12;
    const RenderResult different = runRender(tracer, other);
    EXPECT_NE(0, std::memcmp(one.images.color.pixels.data(), different.images.color.pixels.data(),
                             one.images.color.pixels.size() * sizeof(Color)));
  }
}

TEST(Renderer, CountsOnePrimaryRayPerSample) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  const RenderResult result = runRender(tracer, smallRecipe(2, SamplerType::Sobol));
  const uint64_t samples = 70ull * 45 * 4;
  EXPECT_EQ(result.stats.counters.primary, samples);
  EXPECT_EQ(result.stats.counters.samples, samples);
  EXPECT_EQ(result.stats.counters.secondary, 0u);
  EXPECT_EQ(result.stats.samplesPerPixel, 4u);
}

// Grading one stage in isolation: the student's stage 2 on the reference's stage 1 splats with
// the reference's filters, so its filter weights are the reference's to the bit.
TEST(Renderer, EarlierStagesFromTheReferenceAreTheOnesThatRun) {
  PATHWAY_REQUIRE_REFERENCE();
  if (test::checkingStudentCode()) GTEST_SKIP() << "checks the framework, not your stages";
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  auto weights = [&](const std::string& integrator, EarlierStages earlier) {
    RenderRecipe recipe = smallRecipe(1, SamplerType::Independent);
    recipe.integrator = integrator;
    recipe.earlierStages = earlier;
    recipe.settings.filter = FilterType::Tent;
    return runRender(tracer, recipe).images.weight.pixels;
  };
  const auto reference = weights("stage2@ref", EarlierStages::Own);
  const auto mixed = weights("stage2", EarlierStages::Reference);
  const auto own = weights("stage2", EarlierStages::Own);
  ASSERT_EQ(reference.size(), mixed.size());
  EXPECT_EQ(0, std::memcmp(reference.data(), mixed.data(), reference.size() * sizeof(Color)));
  // The skeleton's own placeholder splat gives other weights: the choice is not a no-op.
  EXPECT_NE(0, std::memcmp(reference.data(), own.data(), reference.size() * sizeof(Color)));
}

class NaNIntegrator : public Integrator {
 public:
  Color Li(const Ray&, SampleStream& samples, const RenderContext&) const override {
    return samples.next1D() < 0.5f ? Color(NAN) : Color(1.0f);
  }
};

TEST(Renderer, DropsAndCountsNonFiniteSamples) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::constantScene(Color(1.0f));
  const RayTracer tracer(scene);
  const Camera camera(scene, 32, 32);
  const NaNIntegrator integrator;
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.samplesPerPixel = 8;
  Renderer renderer(tracer, camera, integrator, test::stage1UnderTest(), settings);
  renderer.renderAll();
  const RayCounters& c = renderer.stats().counters;
  EXPECT_EQ(c.invalidSamples + c.samples, 32u * 32 * 8);
  EXPECT_GT(c.invalidSamples, 32u * 32 * 8 / 3);  // about half, far from the bounds
  EXPECT_GT(c.samples, 32u * 32 * 8 / 3);
  for (const Color& pixel : renderer.film().develop().pixels) {
    ASSERT_TRUE(isFinite(pixel));
  }
}

// Passes without a cancel flag leave their sums in the tile blocks until the film is asked for;
// a cancelled pass must drop its own samples only, whether the passes before it were merged (the
// film was looked at) or not. `twin` renders the same passes, none cancelled.
TEST(Renderer, CancelledPassLeavesTheFilmUntouched) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  const Camera camera(scene, 32, 32);
  const auto integrator = makeIntegrator(1, scene);
  RenderSettings settings;
  settings.width = settings.height = 32;
  settings.samplesPerPixel = 4;
  Renderer renderer(tracer, camera, *integrator, test::stage1UnderTest(), settings);
  Renderer twin(tracer, camera, *integrator, test::stage1UnderTest(), settings);
  auto sameFilm = [&] {
    const Image expected = twin.film().develop(), actual = renderer.film().develop();
    EXPECT_GT(expected.pixels[16 * 32 + 16].x, 0.0f);  // the box room is lit: not an empty film
    return 0 == std::memcmp(expected.pixels.data(), actual.pixels.data(),
                            expected.pixels.size() * sizeof(Color));
  };
  const std::atomic<bool> cancel{true};
  ASSERT_TRUE(renderer.renderPass() && twin.renderPass());
  EXPECT_TRUE(sameFilm());  // looked at: merged
  EXPECT_FALSE(renderer.renderPass(&cancel));
  EXPECT_EQ(renderer.stats().samplesPerPixel, 1u);
  EXPECT_TRUE(sameFilm());
  ASSERT_TRUE(renderer.renderPass() && twin.renderPass());  // not looked at: still in the blocks
  EXPECT_FALSE(renderer.renderPass(&cancel));
  EXPECT_EQ(renderer.stats().samplesPerPixel, 2u);
  EXPECT_TRUE(sameFilm());
  EXPECT_FALSE(renderer.finished());
}

// Sets the cancel flag in the middle of a pass, after `samplesBeforeCancel` calls in all.
class CancellingIntegrator : public Integrator {
 public:
  CancellingIntegrator(std::atomic<bool>& cancel, int samplesBeforeCancel)
      : cancel_(cancel), left_(samplesBeforeCancel) {}
  Color Li(const Ray&, SampleStream& samples, const RenderContext&) const override {
    if (--left_ == 0) cancel_ = true;
    return Color(samples.next1D());
  }

 private:
  std::atomic<bool>& cancel_;
  mutable std::atomic<int> left_;
};

// A pass cancelled part-way has splatted some samples into the blocks already: they must go,
// and the earlier, unmerged pass must stay; the pass after it must find clean blocks. Σw tells
// (and the colour: the integrator returns random values, not a constant).
TEST(Renderer, PassCancelledPartWayDropsItsSamplesOnly) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  const Camera camera(scene, 64, 64);
  RenderSettings settings;
  settings.width = settings.height = 64;
  settings.samplesPerPixel = 4;
  std::atomic<bool> cancel{false}, neverSet{false};
  const int samplesPerPass = 64 * 64;
  const CancellingIntegrator cancelling(cancel, samplesPerPass + samplesPerPass / 3);
  const CancellingIntegrator plain(neverSet, -1);
  Renderer renderer(tracer, camera, cancelling, test::stage1UnderTest(), settings);
  Renderer twin(tracer, camera, plain, test::stage1UnderTest(), settings);
  ASSERT_TRUE(renderer.renderPass() && twin.renderPass());  // not merged yet
  EXPECT_FALSE(renderer.renderPass(&cancel));               // cancelled a third of the way
  EXPECT_EQ(renderer.stats().samplesPerPixel, 1u);
  ASSERT_TRUE(renderer.renderPass() && twin.renderPass());  // the second sample, on both
  for (const auto& [expected, actual] :
       {std::pair{twin.film().weights(), renderer.film().weights()},
        std::pair{twin.film().develop(), renderer.film().develop()}})
    EXPECT_EQ(0, std::memcmp(expected.pixels.data(), actual.pixels.data(),
                             expected.pixels.size() * sizeof(Color)));
}

TEST(Renderer, CancelStopsAPassOfManySamplesPerPixelPromptly) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = test::boxRoom();
  const RayTracer tracer(scene);
  const Camera camera(scene, 64, 64);
  const auto integrator = makeIntegrator(1, scene);
  RenderSettings settings;
  settings.width = settings.height = 64;
  // Hours of work in one pass.
  settings.samplesPerPixel = settings.samplesPerPass = setting::kSamplesPerPixel.maxValue;
  Renderer renderer(tracer, camera, *integrator, test::stage1UnderTest(), settings);
  std::atomic<bool> cancel{false};
  auto pass = std::async(std::launch::async, [&] { return renderer.renderPass(&cancel); });
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto start = std::chrono::steady_clock::now();
  cancel = true;
  ASSERT_EQ(pass.wait_for(std::chrono::seconds(5)), std::future_status::ready);
  EXPECT_FALSE(pass.get());
  // One pixel's samples at most remain after the flag is seen: about 2^20 / 5 M/s = 0.2 s.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 2.0);
  EXPECT_EQ(renderer.stats().samplesPerPixel, 0u);
}

TEST(Renderer, CountsTheRaysOfEveryPixel) {
  PATHWAY_REQUIRE_REFERENCE();
  const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/furnace_closed.gltf");
  const RayTracer tracer(scene);
  const Camera camera(scene, 40, 30);
  const auto integrator = makeIntegrator(4, scene, {{"branching", "2"}, {"depth", "2"}});
  RenderSettings settings;
  settings.width = 40;
  settings.height = 30;
  settings.samplesPerPixel = 3;
  Renderer renderer(tracer, camera, *integrator, test::stage1UnderTest(), settings);
  renderer.renderAll();
  const std::vector<uint64_t>& rays = renderer.raysPerPixel();
  ASSERT_EQ(rays.size(), 40u * 30);
  EXPECT_EQ(std::accumulate(rays.begin(), rays.end(), uint64_t(0)),
            renderer.stats().counters.totalRays());
  // The furnace is closed, so every camera sample casts exactly 1 + 2 + 4 rays.
  EXPECT_EQ(std::count(rays.begin(), rays.end(), 3u * 7u), static_cast<long>(rays.size()));
}

}  // namespace
}  // namespace pathway
