#include "grade/grading_cases.h"

#include <algorithm>
#include <fstream>
#include <map>

#include "core/error.h"
#include "engine/recipe_builder.h"
#include "grade/grading_case_builder.h"
#include "stage_loading/reference_library.h"

namespace pathway {
namespace {

// The required-technique bounds (GradingCase::noiseBound), measured with `grade --calibrate 1000`
// (docs/grading-course.md): the reference and every valid variant stay below a tenth of the bound
// (at most 1.34 on many-rays, 1.90 on the small light, MIS's); one AO ray where 128 are asked for
// reads about 125, always 4 rays about 33, a path tracer without NEE about 10⁵ on the small light
// and 150 on the Cornell box.
constexpr double kFewerAoRaysBound = 15.0;
constexpr double kNoLightSamplingBound = 50.0;
constexpr const char* kLightSampling =
    "stage 5 samples the light at every hit (next-event estimation); a path that finds a light "
    "only by hitting it is far noisier (assignments/stage5/README.md, Required)";

std::vector<GradingCase> declareCases() {
  using B = CaseBuilder;
  const B cases[] = {
      // Stage 1: edges and flat regions under every filter; Mitchell at low spp; each profile.
      B(1, "cornell-box", "cornell_box.gltf",
        "a box stretched over neighbouring pixels: splat reach, half-pixel offsets")
          .filter(FilterType::Box, 0.75f)
          .spp(16)
          .tiles(2),
      B(1, "edges-tent", "grading_edges.gltf", "tent profile and its support over hard edges")
          .filter(FilterType::Tent)
          .size(96, 72)
          .spp(32)
          .tiles(2),
      B(1, "edges-mitchell", "grading_edges.gltf",
        "Mitchell-Netravali lobes at low spp; numerical normalisation")
          .filter(FilterType::MitchellNetravali)
          .size(96, 72)
          .spp(4)
          .tiles(2),
      B(1, "edges-gaussian", "grading_edges.gltf",
        "Gaussian profile and cut-off at a stretched radius")
          .filter(FilterType::Gaussian, 2.5f)
          .size(96, 72)
          .spp(16)
          .tiles(2),
      // The profiles themselves: stripes fill the frame, so every pixel depends on the filter's
      // shape. Each coefficient of each piece 10 % off is caught in 10 of 10 renders at these
      // spp; at 64 spp some were caught in none (docs/grading-course.md).
      // A box wider than a pixel: the skeleton's splat into the one pixel a sample falls in is
      // exactly the box of radius 1/2, so at that radius the untouched skeleton would pass.
      B(1, "stripes-box", "grading_stripes.gltf", "the box's width on stripes of every frequency")
          .filter(FilterType::Box, 0.75f)
          .size(64, 48)
          .spp(256)
          .tiles(2),
      B(1, "stripes-tent", "grading_stripes.gltf", "the tent's slope on stripes of every frequency")
          .filter(FilterType::Tent)
          .size(64, 48)
          .spp(256)
          .tiles(2),
      // 512 spp: 7/3 rounded to 2.33 in the outer piece (its lobe 4.4 % shallower at its deepest,
      // and a step of 0.0044 at |x| = 2) was caught in 64 of 100 renders at 256.
      B(1, "stripes-mitchell", "grading_stripes.gltf",
        "Mitchell-Netravali's profile: each coefficient of both pieces")
          .filter(FilterType::MitchellNetravali)
          .size(64, 48)
          .spp(512)
          .tiles(2),
      B(1, "stripes-gaussian", "grading_stripes.gltf",
        "the Gaussian's width and cut-off on stripes of every frequency")
          .filter(FilterType::Gaussian)
          .size(64, 48)
          .spp(512)
          .tiles(2),
      // Stage 2: cosine weighting, pdf, AO distance.
      // 32 spp: AO rays moved off the surface by a fixed 0.01 instead of spawnRay's offset
      // change the contact shadows by well under 1 % of the image (measured: caught in 0 of 20
      // renders at 8 spp, 20 of 20 at 32).
      B(2, "cornell-box", "cornell_box.gltf", "AO estimate with contact shadows; ray offsets")
          .param("ao-rays", "2")
          .param("ao-distance", "0.3")
          .spp(32),
      B(2, "ceiling", "ceiling.gltf", "cosine weighting and ray length: (h/r)^2")
          .param("ao-rays", "2")
          .param("ao-distance", "2")
          .size(64, 64)
          .spp(8),
      // Many AO rays per hit: one ray where 128 are asked for is about 128 times as noisy.
      B(2, "many-rays", "ceiling.gltf", "the number of AO rays per hit the case asks for")
          .param("ao-rays", "128")
          .param("ao-distance", "2")
          .size(64, 64)
          .spp(8)
          .requiresTechnique(kFewerAoRaysBound,
                             "stage 2 averages the ao-rays AO rays per hit that the case asks for "
                             "(here 128); fewer rays are that much noisier (assignments/stage2/"
                             "README.md, Required)"),
      // 32 spp: the back of back_light is the only back face in view, and an AO frame flipped
      // there was caught in 53 of 100 renders at 8 spp (100 of 100 at 32).
      B(2, "lights", "grading_lights.gltf", "AO in an open room, background for misses")
          .param("ao-rays", "2")
          .param("ao-distance", "0.5")
          .filter(FilterType::Tent)
          .spp(32),
      // Stage 3: the same integral, one 4D point per sample.
      B(3, "cornell-box", "cornell_box.gltf", "4D AO from Sobol' dimensions 2-3")
          .param("ao-distance", "0.3")
          .sobol()
          .spp(16),
      B(3, "corner", "corner.gltf", "AO = 1/4 in an inside corner")
          .param("ao-distance", "1e6")
          .sobol()
          .size(64, 64)
          .spp(16),
      // A reach just past the ceiling: only directions within 11.4° of the normal meet it
      // (AO = (h/r)² = 0.961, from u1 < 0.039 in the reference's warp), so a warp that loses the
      // pole's neighbourhood shows: the pair clamped to [0.05, 0.95] passed every other case.
      B(3, "ceiling-near-pole", "ceiling.gltf",
        "directions close to the normal: (h/r)^2 where the reach barely passes the ceiling")
          .param("ao-distance", "1.02")
          .sobol()
          .size(64, 64)
          .spp(16),
      B(3, "lights", "grading_lights.gltf", "4D AO in an open room")
          .param("ao-distance", "0.5")
          .sobol()
          .spp(16),
      // Stage 4: a small branching factor and depth.
      B(4, "cornell-box", "cornell_box.gltf", "emission plus two bounces of recursion")
          .param("branching", "2")
          .param("depth", "2")
          .spp(8),
      // 32 spp: branches skipped at grazing angles (4 % of the bounce light) were caught in 92 of
      // 100 renders at 8 spp (100 of 100 at 32).
      B(4, "lights", "grading_lights.gltf",
        "direct light by recursion, background, one-sided emitters")
          .param("branching", "3")
          .param("depth", "1")
          .spp(32),
      // Light an emitter reflects: the strip's white front sends back the glow under it, which
      // needs depth 3 to reach the camera (recursion that stops at emitters passed every other
      // case). 16-pixel tiles: rare paths that find the strip make 8-pixel tiles heavy-tailed
      // (the reference failed 30 renders in 1000 there, none with 16).
      B(4, "light-near-floor", "light_near_floor.gltf",
        "light that an emitter reflects: the strip's white front over its own glow")
          .param("branching", "2")
          .param("depth", "3")
          .spp(16)
          .tiles(16),
      // Stage 5: NEE on and off, small and touching lights, one-sided emitters, background, both
      // ways of picking an emitter.
      // 128 spp: continuation rays moved off the surface by a fixed 0.01 instead of spawnRay's
      // offset (measured: caught in 0 of 10 renders at 16 spp, 9 of 10 at 64, 10 of 10 at 128).
      B(5, "cornell-box", "cornell_box.gltf",
        "path tracing with NEE and Russian roulette; ray offsets")
          .spp(128)
          .requiresTechnique(kNoLightSamplingBound, kLightSampling),
      // Two bounces, roulette from the first: the emission found at the depth limit is 13 % of the
      // image's mean, and every path meets the roulette (at the defaults, that emission left out
      // and a roulette drawn from the direction's number were caught in 0 and 67 of 100 renders;
      // here in 100 and 100).
      B(5, "cornell-box-no-nee", "cornell_box.gltf",
        "emission found by bounces, counted once, up to the depth limit; roulette")
          .param("nee", "off")
          .param("max-depth", "2")
          .param("rr-depth", "1")
          .spp(64),
      // No depth limit in a closed room: roulette alone ends the paths, and a q that stays 1
      // never does (it runs past the time limit); every pixel is Le/(1-a) = 2. NEE off: with it,
      // the room's edges (emitters touching walls) give rare huge samples (1 render in 300
      // failed).
      B(5, "furnace-unlimited-depth", "furnace_closed.gltf",
        "paths of any length in a closed room: roulette alone ends them, L = 2")
          .param("max-depth", "-1")
          .param("nee", "off")
          .spp(16),
      // Without NEE a path finds this light only by hitting it: hundreds of times the noise.
      B(5, "small-light", "small_light.gltf",
        "NEE towards a small emitter: the area pdf, and that the light is sampled at all")
          .param("max-depth", "2")
          .size(64, 64)
          .spp(16)
          .requiresTechnique(kNoLightSamplingBound, kLightSampling),
      B(5, "light-touching-wall", "light_touching_wall.gltf",
        "shadow rays that start or end at a contact line")
          .param("max-depth", "3")
          .spp(16),
      // The geometry term at a few centimetres: an estimator that clamps d² near a light (to
      // tame fireflies) darkens the glow around it (measured: max(d², 0.01) is caught in 0 of 100
      // renders on light-touching-wall, whose noise at the contact line hides it; 100 of 100
      // here).
      B(5, "light-near-floor", "light_near_floor.gltf",
        "shadow rays to a light a few centimetres away: 1/d^2 where d is small")
          .param("max-depth", "2")
          .spp(16),
      B(5, "lights-area", "grading_lights.gltf",
        "emitters of different size and radiance, one seen from behind")
          .param("light-pick", "area")
          .spp(32),
      B(5, "lights-power", "grading_lights.gltf",
        "emitters picked by power where power per area differs: the pdf of that picking")
          .spp(32),
  };
  std::vector<GradingCase> result;
  for (const B& b : cases) result.push_back(b.c);
  return result;
}

}  // namespace

RenderRecipe GradingCase::recipe(Variant variant, EarlierStages earlier, uint64_t seed,
                                 ReferenceTracing tracing) const {
  const IntegratorInfo* info = findStageIntegrator(stage, variant);
  if (info && variant == Variant::Reference)
    info = &findIntegrator(referenceIntegratorName(stage, tracing));
  if (!info)
    throw PathwayError(variant == Variant::Reference
                           ? referenceStageMissing(stage)
                           : "the student stage " + std::to_string(stage) +
                                 " is not built into this program");
  // Independent samples unless the case is about Sobol' (stage 3): with them, any valid order in
  // which a student takes dimensions has the variance the reference predicts. (Stage 5 renders
  // with Sobol' by default; its grading cases do not.)
  return RecipeBuilder(*info)
      .params(params)
      .earlierStages(earlier)
      .size(width, height)
      .spp(spp)
      .sampler(sobol ? SamplerType::Sobol : SamplerType::Independent)
      .seed(seed)
      .filter(filter, filterRadius);
}

namespace {

std::vector<GradingCase>& courseCases() {
  static std::vector<GradingCase> cases;
  return cases;
}

}  // namespace

bool addCourseCases(std::vector<GradingCase> cases) {
  for (GradingCase& c : cases) {
    c.courseOnly = true;
    courseCases().push_back(std::move(c));
  }
  return true;
}

const std::vector<GradingCase>& gradingCases() {
  static const std::vector<GradingCase> cases = [] {
    std::vector<GradingCase> all = declareCases();
    all.insert(all.end(), courseCases().begin(), courseCases().end());
    // Each stage's cases together, the shipped ones first: the grader renders a stage at a time.
    std::stable_sort(all.begin(), all.end(),
                     [](const GradingCase& a, const GradingCase& b) { return a.stage < b.stage; });
    return all;
  }();
  return cases;
}

std::string courseCasesNotHere(const std::string& referencesFolder) {
  std::ifstream in(referencesFolder + "/course-cases.txt");
  std::map<int, int> perStage;
  int total = 0;
  for (int stage; in >> stage;) ++perStage[stage], ++total;
  if (total == 0) return "";
  for (const GradingCase& c : gradingCases())
    if (c.courseOnly) return "";  // built in: graded here
  std::string text = "The course's autograder also grades " + std::to_string(total) +
                     " cases of its own that this handout does not have (";
  for (const auto& [stage, count] : perStage)
    text += (text.back() == '(' ? "" : ", ") + std::string("stage ") + std::to_string(stage) +
            ": " + std::to_string(count);
  return text + "): other scenes, sizes and settings, so write the stages, not the images.";
}

std::vector<const GradingCase*> gradingCasesOf(int stage) {
  std::vector<const GradingCase*> result;
  for (const GradingCase& c : gradingCases())
    if (c.stage == stage) result.push_back(&c);
  if (result.empty())
    throw PathwayError("stage " + std::to_string(stage) + " has no grading cases");
  return result;
}

const GradingCase* gradingCaseOrNull(const std::string& id) {
  for (const GradingCase& c : gradingCases())
    if (c.id() == id) return &c;
  return nullptr;
}

const GradingCase& findGradingCase(const std::string& id) {
  if (const GradingCase* found = gradingCaseOrNull(id)) return *found;
  std::string known;
  for (const GradingCase& c : gradingCases()) known += (known.empty() ? "" : ", ") + c.id();
  throw PathwayError("unknown grading case '" + id + "' (known: " + known + ")");
}

}  // namespace pathway
