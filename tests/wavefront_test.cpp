// The wavefront references (stage2@fast, stage3@fast, stage5@fast): the same estimator as the
// single-ray reference, sample by sample, so on these scenes their images equal stageN@ref's bit
// for bit (Embree's 16-ray packets report the same hits as single rays here);
// the same image for any thread count; the same ray counts; and chosen by default wherever a
// reference renders, unless a render asks for one ray at a time.
#include "render/wavefront.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "cluster/command_lines.h"
#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "engine/render_settings.h"
#include "grade/grading_cases.h"
#include "mutant_list.h"
#include "render/integrator_registry.h"
#include "scene/gltf_loader.h"
#include "stage_loading/stage_library.h"
#include "stage_under_test.h"
#include "test_scenes.h"

namespace pathway {
namespace {

std::string scenePath(const std::string& name) {
  return std::string(PATHWAY_SCENES_DIR) + "/" + name;
}

bool haveWavefront() {
  return test::haveReference() &&
         referenceIntegratorName(5, ReferenceTracing::Fastest) == "stage5@fast";
}

#define PATHWAY_REQUIRE_WAVEFRONT() \
  if (!haveWavefront()) GTEST_SKIP() << "no wavefront references in this build"

struct Case {
  std::string scene;
  std::map<std::string, std::string> params;
  SamplerType sampler;
  uint32_t spp;
};

RenderResult render(const RayTracer& tracer, const std::string& integrator, const Case& c,
                    int threads) {
  RenderRecipe recipe = RecipeBuilder(findIntegrator(integrator))
                            .params(c.params)
                            .size(37, 29)  // several tiles, not a multiple of their size
                            .spp(c.spp, 2)
                            .sampler(c.sampler)
                            .seed(5)
                            .threads(threads);
  recipe.settings.tileSize = 16;
  return runRender(tracer, recipe);
}

bool sameBits(const Image& a, const Image& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(Color)) == 0;
}

void expectSameImage(const RenderResult& single, const RenderResult& fast,
                     const std::string& what) {
  EXPECT_TRUE(sameBits(single.images.color, fast.images.color)) << what << ": colour";
  EXPECT_TRUE(sameBits(single.images.variance, fast.images.variance)) << what << ": variance";
  EXPECT_TRUE(sameBits(single.images.weight, fast.images.weight)) << what << ": weight";
  const RayCounters& a = single.stats.counters;
  const RayCounters& b = fast.stats.counters;
  EXPECT_EQ(a.primary, b.primary) << what;
  EXPECT_EQ(a.secondary, b.secondary) << what;
  EXPECT_EQ(a.shadow, b.shadow) << what;
  EXPECT_EQ(a.samples, b.samples) << what;
}

void compareWithSingleRay(int stage, const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    const Scene scene = loadScene(scenePath(c.scene));
    const RayTracer tracer(scene);
    std::string what = c.scene + " " + samplerTypeName(c.sampler);
    for (const auto& [name, value] : c.params) what += " " + name + "=" + value;
    const std::string single = stageIntegratorName(stage, Variant::Reference);
    const std::string fast = referenceIntegratorName(stage, ReferenceTracing::Fastest);
    expectSameImage(render(tracer, single, c, 2), render(tracer, fast, c, 2), what);
  }
}

TEST(WavefrontStages, PathTracerGivesTheSingleRayReferencesImageBitForBit) {
  PATHWAY_REQUIRE_WAVEFRONT();
  compareWithSingleRay(
      5, {{"cornell_box.gltf", {}, SamplerType::Sobol, 8},
          {"cornell_box.gltf",
           {{"nee", "off"}, {"max-depth", "-1"}, {"rr-depth", "1"}, {"light-pick", "area"}},
           SamplerType::Independent,
           8},
          {"small_light.gltf", {{"max-depth", "2"}}, SamplerType::Stratified, 8},
          {"grading_lights.gltf", {{"light-pick", "power"}}, SamplerType::Sobol, 4},
          {"white_furnace.gltf", {{"rr-depth", "0"}}, SamplerType::Independent, 4},
          {"textured_quad.gltf", {}, SamplerType::Sobol, 4}});
}

TEST(WavefrontStages, EyeLightGivesTheSingleRayReferencesImageBitForBit) {
  PATHWAY_REQUIRE_WAVEFRONT();
  compareWithSingleRay(1, {{"cornell_box.gltf", {}, SamplerType::Independent, 4},
                           {"grading_stripes.gltf", {}, SamplerType::Sobol, 8},
                           {"textured_quad.gltf", {}, SamplerType::Stratified, 4}});
}

TEST(WavefrontStages, NestedAmbientOcclusionGivesTheSingleRayReferencesImageBitForBit) {
  PATHWAY_REQUIRE_WAVEFRONT();
  compareWithSingleRay(
      2, {{"cornell_box.gltf", {}, SamplerType::Independent, 4},
          {"ceiling.gltf", {{"ao-rays", "7"}, {"ao-distance", "3"}}, SamplerType::Sobol, 4},
          // More AO rays than a batch holds samples: batches of one packet.
          {"corner.gltf", {{"ao-rays", "200"}}, SamplerType::Stratified, 2}});
}

TEST(WavefrontStages, AmbientOcclusion4DGivesTheSingleRayReferencesImageBitForBit) {
  PATHWAY_REQUIRE_WAVEFRONT();
  compareWithSingleRay(3, {{"cornell_box.gltf", {}, SamplerType::Sobol, 8},
                           {"corner.gltf", {{"ao-distance", "1"}}, SamplerType::Stratified, 8},
                           {"ceiling.gltf", {{"ao-distance", "3"}}, SamplerType::Independent, 4}});
}

// The grader as the equivalence test: for every grading case of the stages that have a
// wavefront version, the first and the last of the replicates a reference is made of (the case's
// own size, filter, sampler, parameters and spp, the replicate's seed) come out of it as out of
// the single-ray reference, bit for bit.
TEST(WavefrontStages, EveryGradingCaseGetsTheSingleRayReferencesReplicates) {
  PATHWAY_REQUIRE_WAVEFRONT();
  for (int stage : {1, 2, 3, 5}) {
    for (const GradingCase* c : gradingCasesOf(stage)) {
      const Scene scene = loadScene(scenePath(c->scene));
      const RayTracer tracer(scene);
      for (const uint64_t replicate : {0, kReferenceReplicates - 1}) {
        auto render = [&](ReferenceTracing tracing) {
          return runRender(tracer, c->recipe(Variant::Reference, EarlierStages::Own,
                                             kReferenceSeed + replicate, tracing));
        };
        expectSameImage(render(ReferenceTracing::SingleRay), render(ReferenceTracing::Fastest),
                        c->id() + " replicate " + std::to_string(replicate));
      }
    }
  }
}

// The comparisons above would pass if both names rendered with one integrator: check that a
// wavefront integrator renders, and that a change to its estimator shows.
TEST(WavefrontStages, TheFastNamesAreWavefrontIntegratorsAndOtherParametersChangeTheImage) {
  PATHWAY_REQUIRE_WAVEFRONT();
  const Scene scene = loadScene(scenePath("cornell_box.gltf"));
  for (int stage : {1, 2, 3, 5}) {
    const IntegratorInfo& info =
        findIntegrator(referenceIntegratorName(stage, ReferenceTracing::Fastest));
    EXPECT_TRUE(info.wavefront) << info.name;
    const StageKit kit = info.kit();
    const auto integrator = info.create({resolveParams(info.name, info.params, {}), kit, scene});
    EXPECT_NE(nullptr, dynamic_cast<const WavefrontIntegrator*>(integrator.get())) << info.name;
  }
  const RayTracer tracer(scene);
  const Case base{"cornell_box.gltf", {}, SamplerType::Sobol, 4};
  const Case other{"cornell_box.gltf", {{"max-depth", "2"}}, SamplerType::Sobol, 4};
  EXPECT_FALSE(sameBits(render(tracer, "stage5@fast", base, 1).images.color,
                        render(tracer, "stage5@fast", other, 1).images.color));
}

TEST(WavefrontStages, OneAndManyThreadsGiveTheSameImage) {
  PATHWAY_REQUIRE_WAVEFRONT();
  const Scene scene = loadScene(scenePath("cornell_box.gltf"));
  const RayTracer tracer(scene);
  for (const char* name : {"stage5@fast", "stage3@fast", "stage2@fast"}) {
    const Case c{"cornell_box.gltf", {}, SamplerType::Sobol, 8};
    const RenderResult one = render(tracer, name, c, 1);
    for (int threads : {2, 5}) {
      const RenderResult many = render(tracer, name, c, threads);
      EXPECT_TRUE(sameBits(one.images.color, many.images.color)) << name << ", " << threads;
      EXPECT_TRUE(sameBits(one.images.variance, many.images.variance)) << name << ", " << threads;
    }
  }
}

TEST(WavefrontStages, OneSampleAtATimeGivesWhatABatchGives) {
  PATHWAY_REQUIRE_WAVEFRONT();
  // Li on a wavefront integrator is a batch of one: the same value as the sample in a batch.
  const Scene scene = loadScene(scenePath("cornell_box.gltf"));
  const RayTracer tracer(scene);
  const IntegratorInfo& info = findIntegrator("stage5@fast");
  const StageKit kit = info.kit();
  const auto made = info.create({resolveParams(info.name, info.params, {}), kit, scene});
  const auto& integrator = dynamic_cast<const WavefrontIntegrator&>(*made);
  const Camera camera(scene, 16, 16);
  const Sampler sampler(SamplerType::Sobol, 64, 3);
  RayCounters counters;
  const RenderContext context(tracer, counters);
  CameraSampleBatch batch;
  std::vector<Color> alone;
  for (uint32_t index = 0; index < 64; ++index) {
    SampleStream samples(sampler, sampler.pixelKey(7, 9), index);
    const Ray ray = camera.generateRay(Vec2(7, 9) + samples.next2D());
    batch.add(ray, samples);
    alone.push_back(integrator.Li(ray, samples, context));
  }
  integrator.LiBatch(batch, context);
  for (size_t i = 0; i < alone.size(); ++i)
    EXPECT_EQ(0, std::memcmp(&alone[i], &batch.radiance[i], sizeof(Color))) << "sample " << i;
}

// What the viewer reads besides the image: rays per pixel (its heatmap), and a cancelled pass
// that leaves the film as it was.
TEST(WavefrontStages, RaysPerPixelMatchAndACancelledPassLeavesTheFilmUntouched) {
  PATHWAY_REQUIRE_WAVEFRONT();
  const Scene scene = loadScene(scenePath("cornell_box.gltf"));
  const RayTracer tracer(scene);
  const Camera camera(scene, 40, 40);
  auto session = [&](const char* name) {
    return std::make_unique<RenderSession>(
        tracer, camera, RecipeBuilder(name).size(40, 40).spp(4, 1).seed(2).recipe());
  };
  const auto single = session("stage5@ref"), fast = session("stage5@fast"),
             twin = session("stage5@fast");
  ASSERT_TRUE(single->renderer().renderPass() && fast->renderer().renderPass() &&
              twin->renderer().renderPass());
  EXPECT_EQ(single->renderer().raysPerPixel(), fast->renderer().raysPerPixel());
  const std::atomic<bool> cancel{true};
  EXPECT_FALSE(fast->renderer().renderPass(&cancel));
  EXPECT_EQ(fast->renderer().stats().samplesPerPixel, 1u);
  EXPECT_TRUE(sameBits(twin->renderer().film().develop(), fast->renderer().film().develop()));
  EXPECT_EQ(twin->renderer().raysPerPixel(), fast->renderer().raysPerPixel());
}

TEST(WavefrontStages, ReferencesRenderWithTheWavefrontVersionUnlessAskedForSingleRays) {
  PATHWAY_REQUIRE_WAVEFRONT();
  EXPECT_EQ("stage5@fast", referenceIntegratorName(5, ReferenceTracing::Fastest));
  EXPECT_EQ("stage5@ref", referenceIntegratorName(5, ReferenceTracing::SingleRay));
  EXPECT_EQ("stage4@ref", referenceIntegratorName(4, ReferenceTracing::Fastest));  // none
  EXPECT_EQ("stage3@fast", referenceIntegratorFor("stage3@ref", ReferenceTracing::Fastest));
  EXPECT_EQ("stage3@ref", referenceIntegratorFor("stage3@ref", ReferenceTracing::SingleRay));
  EXPECT_EQ("stage3", referenceIntegratorFor("stage3", ReferenceTracing::Fastest));  // yours
  EXPECT_EQ("stage5@fast", referenceIntegratorFor("stage5@fast", ReferenceTracing::SingleRay));

  const GradingCase& c = *gradingCasesOf(5).front();
  EXPECT_EQ("stage5@fast", c.recipe(Variant::Reference, EarlierStages::Own, 1).integrator);
  EXPECT_EQ(
      "stage5@ref",
      c.recipe(Variant::Reference, EarlierStages::Own, 1, ReferenceTracing::SingleRay).integrator);
  EXPECT_EQ("stage5", c.recipe(Variant::Student, EarlierStages::Own, 1).integrator);

  EXPECT_EQ(std::vector<std::string>({"-istage2@fast"}), withFastestReference({"-istage2@ref"}));
  const std::vector<std::string> given = {"scene.gltf",   "-i",         "stage5@ref",
                                          "--integrator", "stage1@ref", "--integrator=stage3@ref",
                                          "-p",           "nee=off"};
  const std::vector<std::string> expected = {"scene.gltf",  "-i",
                                             "stage5@fast", "--integrator",
                                             "stage1@fast", "--integrator=stage3@fast",
                                             "-p",          "nee=off"};
  EXPECT_EQ(expected, withFastestReference(given));
}

#ifdef PATHWAY_MUTANT_LIST
// The grader's planted bugs are solution files built as a student's library. Loading one must
// leave the reference's "stageN@fast" in place: a stage-2 bug's own wave would otherwise render
// the references of stages 2 and 3 in that process (as `pathway grade --calibrate` does).
TEST(WavefrontStages, ALibraryBuiltFromASolutionFileKeepsTheReferencesFastVersions) {
  PATHWAY_REQUIRE_WAVEFRONT();
  std::string library;
  for (const test::Mutant& mutant : test::mutants())
    if (mutant.name == "s2_missing_cosine") library = mutant.library;
  ASSERT_FALSE(library.empty()) << "s2_missing_cosine is not in " << PATHWAY_MUTANT_LIST;
  // In a child process: a loaded library stays loaded, and its stage 2 replaces this one's.
  EXPECT_EXIT(
      {
        const size_t before = registrationLog().size();
        loadStageLibrary(library);
        bool replaced = false;
        for (size_t i = before; i < registrationLog().size(); ++i)
          replaced = replaced || registrationLog()[i].find("@fast") != std::string::npos;
        std::_Exit(replaced ? 1 : 0);
      },
      ::testing::ExitedWithCode(0), "");
}
#endif  // PATHWAY_MUTANT_LIST

}  // namespace
}  // namespace pathway
