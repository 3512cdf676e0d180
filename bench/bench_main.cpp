// pathway_bench: the measurements the issues ask for, printed as tables (run by scripts/bench).
//
//   pathway_bench rays   [scene] [--width W] [--repeats R]   raw Embree vs the framework, rays/s
//   pathway_bench stages [scene] [--width W] [--repeats R]   each stage vs raw Embree, same rays
//   pathway_bench memory SCENE                                resident bytes per triangle, BVH
//                                                             build
//   pathway_bench startup [--repeats R]                    start-up and time to the first ray
//   pathway_bench growth [scene] [--out DIR] [--max-triangles N] [--width W] [--repeats R]
//                                       how cost grows: the tables of bench/growth.h, as CSV too
//   pathway_bench ceiling [scene] [--width W] [--spp N] [--repeats R]
//                                       stage5@ref vs a minimal path tracer on raw Embree
//   pathway_bench fast [scene] [--width W] [--spp N] [--repeats R] [--calibrate SEEDS]
//                                       the wavefront references vs the single-ray ones
//   pathway_bench floor [scene] [--width W] [--spp N] [--repeats R]
//                                       stage5@fast vs Embree's traversal of its rays alone
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_kit.h"
#include "ceiling.h"
#include "core/error.h"
#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "engine/render_settings.h"
#include "fast.h"
#include "growth.h"
#include "scene/gltf_loader.h"
#include "startup.h"
#include "traversal_floor.h"

namespace pathway::bench {
namespace {

// A diffuse bounce through the renderer: camera ray, then one cosine-distributed closest-hit ray.
class DiffuseBounceIntegrator : public Integrator {
 public:
  Color Li(const Ray& cameraRay, SampleStream& samples,
           const RenderContext& context) const override {
    const auto hit = context.intersect(cameraRay, RayKind::Primary);
    if (!hit) return Color(0.0f);
    const Vec2 u = samples.next2D();
    const Ray bounce = hit->spawnRay(cosineDirection(hit->normal, u.x, u.y));
    const auto next = context.intersect(bounce, RayKind::Secondary);
    return next ? next->albedo : Color(1.0f);
  }
};
const bool registered = registerIntegrator(
    {"bench-bounce",
     0,
     Variant::Reference,
     "benchmark: camera ray + one diffuse bounce",
     {},
     SamplerType::Independent,
     [](const IntegratorSetup&) { return std::make_unique<DiffuseBounceIntegrator>(); }});

int benchRays(const std::string& scenePath, int width, int repeats) {
  const Scene scene = loadScene(scenePath);
  const RayTracer tracer(scene);
  const RawEmbree raw(scene);
  const RaySets rays = makeRays(scene, tracer, width, width);
  std::printf("scene %s, %zu triangles, %d threads, %dx%d rays, best of %d runs\n\n",
              scenePath.c_str(), scene.triangleCount(), tbb::info::default_concurrency(), width,
              width, repeats);

  auto rate = [](size_t count, double seconds) { return count / seconds * 1e-6; };
  // Raw Embree, one ray at a time and (in turns with it) sixteen at a time through
  // rtcIntersect16: what a renderer that traced many paths' rays together (a wavefront renderer)
  // could gain over single rays. Returns {single, packet} seconds, the best of each.
  auto measureRaw = [&](const std::vector<Ray>& set) {
    std::vector<float> sink(set.size());
    const size_t packets = (set.size() + 15) / 16;
    double single = 1e30, packet = 1e30;
    for (int r = 0; r < repeats; ++r) {
      single = std::min(single, secondsOf([&] {
                          tbb::parallel_for(size_t(0), set.size(),
                                            [&](size_t i) { sink[i] = raw.intersect(set[i]); });
                        }));
      packet = std::min(packet, secondsOf([&] {
                          tbb::parallel_for(size_t(0), packets, [&](size_t p) {
                            const size_t first = 16 * p;
                            raw.intersect16(&set[first], std::min<size_t>(16, set.size() - first),
                                            &sink[first]);
                          });
                        }));
    }
    return std::pair{single, packet};
  };
  auto measureApi = [&](const std::vector<Ray>& set) {
    std::vector<float> sink(set.size());
    return bestSeconds(repeats, [&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, set.size()), [&](const auto& range) {
        RayCounters counters;
        for (size_t i = range.begin(); i != range.end(); ++i) {
          const auto hit = tracer.intersect(set[i], RayKind::Secondary, counters);
          sink[i] = hit ? hit->distance : kInfinity;
        }
      });
    });
  };
  const auto [rawPrimary, packetPrimary] = measureRaw(rays.primary);
  const auto [rawBounce, packetBounce] = measureRaw(rays.incoherent);
  const double apiPrimary = measureApi(rays.primary), apiBounce = measureApi(rays.incoherent);
  uint64_t rendererPrimaryRays = 0, rendererBounceRays = 0;
  const double rendererPrimary =
      rendererSeconds(scene, tracer, "stage1@ref", {}, width, 1, repeats, &rendererPrimaryRays);
  const double rendererBounce =
      rendererSeconds(scene, tracer, "bench-bounce", {}, width, 1, repeats, &rendererBounceRays);

  std::printf("%-40s %12s %10s\n", "ray set / path", "Mrays/s", "vs raw");
  auto row = [](const char* name, double mrays, double rawMrays) {
    std::printf("%-40s %12.2f %10.2f\n", name, mrays, mrays / rawMrays);
  };
  const double rawP = rate(rays.primary.size(), rawPrimary);
  const double rawB = rate(rays.incoherent.size(), rawBounce);
  row("primary: raw Embree rtcIntersect1", rawP, rawP);
  row("primary: RayTracer::intersect", rate(rays.primary.size(), apiPrimary), rawP);
  row("primary: renderer (stage1@ref, box, 1 spp)", rate(rendererPrimaryRays, rendererPrimary),
      rawP);
  row("diffuse bounce: raw Embree rtcIntersect1", rawB, rawB);
  row("diffuse bounce: RayTracer::intersect", rate(rays.incoherent.size(), apiBounce), rawB);
  // The renderer's bounce path mixes one primary and one bounce ray per sample; compare it with
  // raw Embree tracing the same mix.
  const double rawMix =
      (rays.primary.size() + rays.incoherent.size()) / (rawPrimary + rawBounce) * 1e-6;
  row("camera + bounce: raw Embree (same mix)", rawMix, rawMix);
  row("camera + bounce: renderer (bench-bounce)", rate(rendererBounceRays, rendererBounce), rawMix);
  row("primary: raw Embree rtcIntersect16", rate(rays.primary.size(), packetPrimary), rawP);
  row("diffuse bounce: raw Embree rtcIntersect16", rate(rays.incoherent.size(), packetBounce),
      rawB);

  // What the BVH flags cost. Pathway always traces robustly (rays through shared edges never
  // slip between triangles: the closed-furnace and watertightness tests need it); it builds
  // compact BVHs only for large scenes (ray_tracer.h), where the memory per triangle matters.
  std::printf("\n%-40s %12s %10s\n", "Embree scene flags (raw)", "Mrays/s", "vs 1st");
  const RTCSceneFlags flagSets[] = {RTC_SCENE_FLAG_ROBUST,
                                    RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT,
                                    RTC_SCENE_FLAG_NONE, RTC_SCENE_FLAG_COMPACT};
  const char* flagNames[] = {"robust", "robust + compact", "neither", "compact"};
  for (const auto* set : {&rays.primary, &rays.incoherent}) {
    // Interleaved, best of `repeats` each: every flag set sees the same moments of load.
    std::vector<std::unique_ptr<RawEmbree>> bvhs;
    for (RTCSceneFlags flags : flagSets) bvhs.push_back(std::make_unique<RawEmbree>(scene, flags));
    std::vector<double> best(bvhs.size(), 1e30);
    for (int r = 0; r < repeats; ++r)
      for (size_t i = 0; i < bvhs.size(); ++i) {
        const std::vector<Ray>& rayList = *set;
        std::vector<float> sink(rayList.size());
        best[i] = std::min(best[i], secondsOf([&] {
                             tbb::parallel_for(size_t(0), rayList.size(), [&](size_t k) {
                               sink[k] = bvhs[i]->intersect(rayList[k]);
                             });
                           }));
      }
    for (size_t i = 0; i < bvhs.size(); ++i)
      row((std::string(set == &rays.primary ? "primary: " : "diffuse bounce: ") + flagNames[i])
              .c_str(),
          rate(set->size(), best[i]), rate(set->size(), best[0]));
  }
  return 0;
}

int benchStages(const std::string& scenePath, int width, int repeats) {
  const Scene scene = loadScene(scenePath);
  RayTracer tracer(scene);
  const RawEmbree raw(scene);
  std::printf(
      "scene %s, %dx%d, %d threads; renderer: best of %d passes after a warm-up;\n"
      "raw: the same pass's rays, recorded, traced by rtcIntersect1/rtcOccluded1\n\n",
      scenePath.c_str(), width, width, tbb::info::default_concurrency(), repeats);
  std::printf("%-22s %14s %12s %12s %8s\n", "integrator", "rays/sample", "Mrays/s", "raw Mrays/s",
              "ratio");
  for (const StageCase& c : kStageCases) {
    uint64_t rays = 0;
    const double seconds =
        rendererSeconds(scene, tracer, c.integrator, c.params, width, c.spp, repeats, &rays);
    const std::vector<LoggedRay> log =
        recordRays(scene, tracer, c.integrator, c.params, width, c.spp);
    const double rawSeconds = replaySeconds(raw, log, repeats);
    const double mrays = rays / seconds * 1e-6, rawMrays = log.size() / rawSeconds * 1e-6;
    const std::string label = caseLabel(c.integrator, c.params);
    std::printf("%-22s %14.2f %12.2f %12.2f %8.2f\n", label.c_str(),
                double(rays) / (double(width) * width * c.spp), mrays, rawMrays, mrays / rawMrays);
  }

  // The fixed workload: stage 5 at 256x256, 64 spp, 5 bounces, as the CLI runs it.
  const RenderRecipe recipe = RecipeBuilder("stage5@ref")
                                  .param("max-depth", "5")
                                  .size(256, 256)
                                  .spp(64, 4)
                                  .sampler(SamplerType::Independent);  // as measured since
  double wall = 0.0;
  RenderResult result;
  wall = secondsOf([&] { result = runRender(tracer, recipe); });
  std::printf(
      "\nstage5@ref 256x256, 64 spp, max-depth 5: %.2f s wall, %.2f Mrays/s "
      "(%llu rays: %llu primary, %llu secondary, %llu shadow)\n",
      wall, result.stats.counters.totalRays() / wall * 1e-6,
      static_cast<unsigned long long>(result.stats.counters.totalRays()),
      static_cast<unsigned long long>(result.stats.counters.primary),
      static_cast<unsigned long long>(result.stats.counters.secondary),
      static_cast<unsigned long long>(result.stats.counters.shadow));
  return 0;
}

int benchMemory(const std::string& scenePath) {
  const long before = residentBytes();
  Scene scene;
  const double loadSeconds = secondsOf([&] { scene = loadScene(scenePath); });
  const long afterLoad = residentBytes();
  std::unique_ptr<RayTracer> tracer;
  const double buildSeconds = secondsOf([&] { tracer = std::make_unique<RayTracer>(scene); });
  const long afterBuild = residentBytes();
  const double triangles = static_cast<double>(scene.triangleCount());
  std::printf("scene %s: %.0f triangles, %zu meshes\n", scenePath.c_str(), triangles,
              scene.meshes.size());
  std::printf("load %.2f s, BVH build %.2f s (%d threads)\n", loadSeconds, buildSeconds,
              tbb::info::default_concurrency());
  std::printf("resident bytes per triangle: scene %.1f, BVH %.1f, total %.1f\n",
              (afterLoad - before) / triangles, (afterBuild - afterLoad) / triangles,
              (afterBuild - before) / triangles);
  std::printf("Embree's own count of BVH bytes per triangle: %.1f\n",
              tracer->bvhBytes() / triangles);
  return 0;
}

// ---- Command line ----

constexpr const char* kUsage =
    "usage: pathway_bench rays   [scene] [--width W] [--repeats R]\n"
    "       pathway_bench stages [scene] [--width W] [--repeats R]\n"
    "       pathway_bench memory SCENE\n"
    "       pathway_bench startup [--repeats R]\n"
    "       pathway_bench growth [scene] [--out DIR] [--max-triangles N] [--width W] "
    "[--repeats R]\n"
    "       pathway_bench ceiling [scene] [--width W] [--spp N] [--repeats R]\n"
    "       pathway_bench fast [scene] [--width W] [--spp N] [--repeats R] [--calibrate SEEDS]\n"
    "       pathway_bench floor [scene] [--width W] [--spp N] [--repeats R]\n"
    "  rays:   raw Embree vs the framework, rays/s (default scene: the Cornell box; width 512,\n"
    "          best of 5 repeats; growth: best of 10)\n"
    "  stages: every stage vs raw Embree on the same rays\n"
    "  memory: resident bytes per triangle and BVH build time of a scene\n"
    "  startup: how long `pathway` commands take to start and to reach their first ray (median\n"
    "           of 7 runs)\n"
    "  growth: how cost grows, in one run: stages vs raw Embree, 1 vs 2 threads, cost vs spp,\n"
    "          BVH build time and bytes per triangle for generated grids of 10k to N triangles\n"
    "          (N from 10k to 100M, default 10M); --out DIR also writes the tables as CSV\n"
    "          (scripts/draw_growth.py DIR draws them)\n"
    "  ceiling: stage5@ref vs a minimal path tracer on raw Embree, the same image rendered in\n"
    "           turns (width 256, 64 spp, best of 3); exit status 1 when their global means\n"
    "           differ by more than 1 % (or 4 standard errors, when noise is larger)\n"
    "  fast:   stageN@fast vs stageN@ref: renders in turns, agreement, and grade\n"
    "          --make-references / --calibrate SEEDS with and without --single-ray\n"
    "  floor:  stage2/3/5@fast's renders vs their own rays replayed through raw Embree packets\n"
    "          (robust and non-robust BVH), for the image (width 256, 64 spp) and, stages 3 and\n"
    "          5, the viewer's pane\n";

// A mistake on the command line: one message, the usage is not repeated.
struct UsageError : PathwayError {
  using PathwayError::PathwayError;
};

// A whole number in [minValue, maxValue]; `suffixes` also takes 20k and 10M.
uint64_t parseCount(const std::string& option, const std::string& text, uint64_t minValue,
                    uint64_t maxValue, bool suffixes = false) {
  uint64_t scale = 1;
  std::string digits = text;
  if (suffixes && !digits.empty() && (digits.back() == 'k' || digits.back() == 'M')) {
    scale = digits.back() == 'k' ? 1'000 : 1'000'000;
    digits.pop_back();
  }
  const bool wellFormed =
      !digits.empty() && digits.find_first_not_of("0123456789") == std::string::npos;
  // Past 12 digits the value is out of every range here, and could overflow.
  const uint64_t value = !wellFormed          ? 0
                         : digits.size() > 12 ? UINT64_MAX
                                              : std::stoull(digits) * scale;
  const std::string got = ", got '" + text + "'";
  if (!wellFormed)
    throw UsageError(option + " expects a whole number" +
                     (suffixes ? " (20k and 10M also work)" : "") + got);
  if (value < minValue)
    throw UsageError(option + " must be at least " + std::to_string(minValue) + got);
  if (value > maxValue)
    throw UsageError(option + " must be at most " + std::to_string(maxValue) + got);
  return value;
}

struct Arguments {
  std::string mode;
  std::optional<std::string> scene;
  std::optional<int> width, repeats;
  std::optional<uint32_t> spp;
  std::optional<std::string> outDir;
  std::optional<uint64_t> maxTriangles;
  std::optional<int> calibrationSeeds;
};

Arguments parseArguments(int argc, char** argv) {
  Arguments args;
  args.mode = argv[1];
  if (args.mode != "rays" && args.mode != "stages" && args.mode != "memory" &&
      args.mode != "growth" && args.mode != "startup" && args.mode != "ceiling" &&
      args.mode != "fast" && args.mode != "floor")
    throw UsageError("unknown mode '" + args.mode +
                     "' (rays, stages, memory, growth, startup, ceiling, fast or floor)");
  for (int i = 2; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw UsageError(arg + " needs a value");
      return argv[++i];
    };
    auto onlyFor = [&](const std::string& mode) {
      if (args.mode != mode) throw UsageError(arg + " is an option of `" + mode + "` only");
    };
    if (arg == "--width") {
      args.width = static_cast<int>(
          parseCount(arg, value(), 1, static_cast<uint64_t>(setting::kWidth.maxValue)));
    } else if (arg == "--repeats") {
      args.repeats = static_cast<int>(parseCount(arg, value(), 1, 1000));
    } else if (arg == "--calibrate") {
      onlyFor("fast");
      args.calibrationSeeds = static_cast<int>(parseCount(arg, value(), 0, 100000, true));
    } else if (arg == "--spp") {
      if (args.mode != "ceiling" && args.mode != "fast" && args.mode != "floor")
        throw UsageError(arg + " is an option of `ceiling`, `fast` and `floor` only");
      args.spp = static_cast<uint32_t>(parseCount(arg, value(), setting::kSamplesPerPixel.minValue,
                                                  setting::kSamplesPerPixel.maxValue));
    } else if (arg == "--out") {
      onlyFor("growth");
      args.outDir = value();
    } else if (arg == "--max-triangles") {
      onlyFor("growth");
      args.maxTriangles = parseCount(arg, value(), kMinGrowthTriangles, kMaxGrowthTriangles, true);
    } else if (arg.rfind("--", 0) == 0) {
      throw UsageError("unknown option " + arg);
    } else if (args.scene) {
      throw UsageError("one scene only, got '" + *args.scene + "' and '" + arg + "'");
    } else {
      args.scene = arg;
    }
  }
  if (args.mode == "memory" && !args.scene) throw UsageError("memory needs a scene file");
  if (args.mode == "memory" && (args.width || args.repeats))
    throw UsageError("memory takes a scene only");
  return args;
}

// The options every mode that renders one image shares, from the command line or their defaults.
template <typename Options>
Options imageOptions(const Arguments& args, const std::string& scene) {
  Options options;
  options.scene = scene;
  options.width = args.width.value_or(options.width);
  options.samplesPerPixel = args.spp.value_or(options.samplesPerPixel);
  options.repeats = args.repeats.value_or(options.repeats);
  return options;
}

int run(const Arguments& args) {
  const std::string scene = args.scene.value_or(PATHWAY_DEFAULT_SCENE);
  if (args.mode == "rays")
    return benchRays(scene, args.width.value_or(512), args.repeats.value_or(5));
  if (args.mode == "stages")
    return benchStages(scene, args.width.value_or(512), args.repeats.value_or(5));
  if (args.mode == "memory") return benchMemory(scene);
  if (args.mode == "startup") {
    if (args.scene || args.width) throw UsageError("startup takes --repeats only");
    return benchStartup(args.repeats.value_or(7));
  }
  if (args.mode == "ceiling") return benchCeiling(imageOptions<CeilingOptions>(args, scene));
  if (args.mode == "fast") {
    FastOptions fast = imageOptions<FastOptions>(args, scene);
    fast.calibrationSeeds = args.calibrationSeeds.value_or(fast.calibrationSeeds);
    return benchFast(fast);
  }
  if (args.mode == "floor") return benchFloor(imageOptions<FloorOptions>(args, scene));
  GrowthOptions growth;
  growth.scene = scene;
  growth.width = args.width.value_or(growth.width);
  growth.repeats = args.repeats.value_or(growth.repeats);
  growth.outDir = args.outDir.value_or("");
  growth.maxTriangles = args.maxTriangles.value_or(growth.maxTriangles);
  return benchGrowth(growth);
}

}  // namespace
}  // namespace pathway::bench

int main(int argc, char** argv) {
  using namespace pathway::bench;
  if (argc < 2) {
    std::fputs(kUsage, stderr);
    return 2;
  }
  try {
    // The growth table's own children: `growth-grid-child CELLS WIDTH REPEATS`, not for people.
    if (argv[1] == std::string(kGrowthChildMode) && argc == 5)
      return growthGridChild(std::stoi(argv[2]), std::stoi(argv[3]), std::stoi(argv[4]));
    return run(parseArguments(argc, argv));
  } catch (const UsageError& error) {
    std::fprintf(stderr, "pathway_bench: %s\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pathway_bench: error: %s\n", error.what());
    return 1;
  }
}
