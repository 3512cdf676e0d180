// pathway_bench: the measurements the issues ask for, printed as tables (run by scripts/bench).
//
//   pathway_bench rays   [scene] [--width W] [--repeats R]   raw Embree vs the framework, rays/s
//   pathway_bench stages [scene] [--width W] [--repeats R]   each stage vs raw Embree, same rays
//   pathway_bench memory SCENE                                resident bytes per triangle, BVH
//   build
#include <embree3/rtcore.h>
#include <tbb/parallel_for.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/error.h"
#include "render/render_session.h"
#include "sampling/pcg32.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Best of `repeats` runs: the least disturbed by other processes on a shared machine.
double bestSeconds(int repeats, const std::function<void()>& work) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) best = std::min(best, secondsOf(work));
  return best;
}

// ---- Raw Embree: the same arrays, no framework in between. ----
struct RawEmbree {
  RTCDevice device = rtcNewDevice(nullptr);
  RTCScene scene = rtcNewScene(device);

  explicit RawEmbree(const Scene& s) {
    rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
    for (uint32_t i = 0; i < s.meshes.size(); ++i) {
      RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                 s.meshes[i].positions.data(), 0, sizeof(Vec3),
                                 s.meshes[i].positions.size());
      rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                 s.meshes[i].triangles.data(), 0, sizeof(glm::uvec3),
                                 s.meshes[i].triangles.size());
      rtcCommitGeometry(g);
      rtcAttachGeometryByID(scene, g, i);
      rtcReleaseGeometry(g);
    }
    rtcCommitScene(scene);
  }
  ~RawEmbree() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
  // Returns the hit distance, or infinity.
  float intersect(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh;
    rh.ray.org_x = ray.origin.x, rh.ray.org_y = ray.origin.y, rh.ray.org_z = ray.origin.z;
    rh.ray.dir_x = ray.direction.x, rh.ray.dir_y = ray.direction.y, rh.ray.dir_z = ray.direction.z;
    rh.ray.tnear = 0.0f, rh.ray.tfar = ray.tMax, rh.ray.time = 0.0f;
    rh.ray.mask = 0xFFFFFFFFu, rh.ray.id = 0, rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene, &context, &rh);
    return rh.hit.geomID == RTC_INVALID_GEOMETRY_ID ? kInfinity : rh.ray.tfar;
  }
  bool occluded(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay r;
    r.org_x = ray.origin.x, r.org_y = ray.origin.y, r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x, r.dir_y = ray.direction.y, r.dir_z = ray.direction.z;
    r.tnear = 0.0f, r.tfar = ray.tMax, r.time = 0.0f;
    r.mask = 0xFFFFFFFFu, r.id = 0, r.flags = 0;
    rtcOccluded1(scene, &context, &r);
    return r.tfar < 0.0f;
  }
};

Vec3 cosineDirection(const Vec3& normal, float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  return Frame(normal).toWorld(Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0f - u1)));
}

// Camera rays through jittered pixel positions, and from their hits cosine-distributed rays.
struct RaySets {
  std::vector<Ray> primary;
  std::vector<Ray> incoherent;
};

RaySets makeRays(const Scene& scene, const RayTracer& tracer, int width, int height) {
  RaySets sets;
  const Camera camera(scene, width, height);
  Pcg32 rng(1);
  RayCounters ignored;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const Ray ray = camera.generateRay(Vec2(x + rng.nextFloat(), y + rng.nextFloat()));
      sets.primary.push_back(ray);
      if (const auto hit = tracer.intersect(ray, RayKind::Primary, ignored))
        sets.incoherent.push_back(
            hit->spawnRay(cosineDirection(hit->normal, rng.nextFloat(), rng.nextFloat())));
    }
  }
  return sets;
}

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

// Steady-state rate of the renderer: one warm-up pass (first touch of the film and tile memory),
// then the best of `repeats` timed passes, `spp` samples per pixel each.
double rendererSeconds(const Scene& scene, const RayTracer& tracer, const std::string& name,
                       const std::map<std::string, std::string>& params, int width, uint32_t spp,
                       int repeats, uint64_t* raysPerPass) {
  const IntegratorInfo& info = findIntegrator(name);
  RenderRecipe recipe;
  recipe.integrator = name;
  recipe.params = resolveParams(name, info.params, params);
  recipe.settings.width = recipe.settings.height = width;
  recipe.settings.samplesPerPixel = spp * (1 + repeats);
  recipe.settings.samplesPerPass = spp;
  recipe.settings.sampler = info.defaultSampler;
  RenderSession session(tracer, Camera(scene, width, width), recipe);
  Renderer& renderer = session.renderer();
  renderer.renderPass();
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) {
    const uint64_t before = renderer.stats().counters.totalRays();
    best = std::min(best, secondsOf([&] { renderer.renderPass(); }));
    *raysPerPass = renderer.stats().counters.totalRays() - before;
  }
  return best;
}

int benchRays(const std::string& scenePath, int width, int repeats) {
  const Scene scene = loadScene(scenePath);
  const RayTracer tracer(scene);
  const RawEmbree raw(scene);
  const RaySets rays = makeRays(scene, tracer, width, width);
  std::printf("scene %s, %zu triangles, %d threads, %dx%d rays, best of %d runs\n\n",
              scenePath.c_str(), scene.triangleCount(), tbb::info::default_concurrency(), width,
              width, repeats);

  auto rate = [](size_t count, double seconds) { return count / seconds * 1e-6; };
  auto measureRaw = [&](const std::vector<Ray>& set) {
    std::vector<float> sink(set.size());
    return bestSeconds(repeats, [&] {
      tbb::parallel_for(size_t(0), set.size(), [&](size_t i) { sink[i] = raw.intersect(set[i]); });
    });
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
  const double rawPrimary = measureRaw(rays.primary), apiPrimary = measureApi(rays.primary);
  const double rawBounce = measureRaw(rays.incoherent), apiBounce = measureApi(rays.incoherent);
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
  return 0;
}

// Every ray one pass of the stage traces, recorded from a single-threaded render.
std::vector<LoggedRay> recordRays(const Scene& scene, RayTracer& tracer, const std::string& name,
                                  const std::map<std::string, std::string>& params, int width,
                                  uint32_t spp) {
  std::vector<LoggedRay> log;
  tracer.setRayLog(&log);
  const IntegratorInfo& info = findIntegrator(name);
  RenderRecipe recipe;
  recipe.integrator = name;
  recipe.params = resolveParams(name, info.params, params);
  recipe.settings.width = recipe.settings.height = width;
  recipe.settings.samplesPerPixel = recipe.settings.samplesPerPass = spp;
  recipe.settings.threads = 1;
  recipe.settings.sampler = info.defaultSampler;
  runRender(tracer, Camera(scene, width, width), recipe);
  tracer.setRayLog(nullptr);
  return log;
}

double replaySeconds(const RawEmbree& raw, const std::vector<LoggedRay>& log, int repeats) {
  std::vector<char> sink(log.size());
  return bestSeconds(repeats, [&] {
    tbb::parallel_for(size_t(0), log.size(), [&](size_t i) {
      const LoggedRay& r = log[i];
      sink[i] = r.occlusionOnly ? raw.occluded(r.ray) : raw.intersect(r.ray) < kInfinity;
    });
  });
}

int benchStages(const std::string& scenePath, int width, int repeats) {
  const Scene scene = loadScene(scenePath);
  RayTracer tracer(scene);
  const RawEmbree raw(scene);
  std::printf(
      "scene %s, %dx%d, %d threads; renderer: best of %d passes after a warm-up;\n"
      "raw: the same pass's rays, recorded, traced by rtcIntersect1/rtcOccluded1\n\n",
      scenePath.c_str(), width, width, tbb::info::default_concurrency(), repeats);
  struct Case {
    const char* name;
    std::map<std::string, std::string> params;
    uint32_t spp;
  };
  const Case cases[] = {
      {"stage1@ref", {}, 4}, {"stage2@ref", {}, 2}, {"stage3@ref", {}, 4},
      {"stage4@ref", {}, 1}, {"stage5@ref", {}, 2}, {"stage5@ref", {{"nee", "off"}}, 2},
  };
  std::printf("%-22s %14s %12s %12s %8s\n", "integrator", "rays/sample", "Mrays/s", "raw Mrays/s",
              "ratio");
  for (const Case& c : cases) {
    uint64_t rays = 0;
    const double seconds =
        rendererSeconds(scene, tracer, c.name, c.params, width, c.spp, repeats, &rays);
    const std::vector<LoggedRay> log = recordRays(scene, tracer, c.name, c.params, width, c.spp);
    const double rawSeconds = replaySeconds(raw, log, repeats);
    const double mrays = rays / seconds * 1e-6, rawMrays = log.size() / rawSeconds * 1e-6;
    std::string label = c.name;
    for (const auto& [key, value] : c.params) label += " " + key + "=" + value;
    std::printf("%-22s %14.2f %12.2f %12.2f %8.2f\n", label.c_str(),
                double(rays) / (double(width) * width * c.spp), mrays, rawMrays, mrays / rawMrays);
  }

  // The fixed workload: stage 5 at 256x256, 64 spp, 5 bounces, as the CLI runs it.
  RenderRecipe recipe;
  recipe.integrator = "stage5@ref";
  recipe.params = resolveParams(recipe.integrator, findIntegrator(recipe.integrator).params,
                                {{"max-depth", "5"}});
  recipe.settings.width = recipe.settings.height = 256;
  recipe.settings.samplesPerPixel = 64;
  recipe.settings.samplesPerPass = 4;
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

long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
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

}  // namespace
}  // namespace pathway

int main(int argc, char** argv) {
  try {
    const std::string mode = argc > 1 ? argv[1] : "";
    std::string scene = PATHWAY_DEFAULT_SCENE;
    int width = 512, repeats = 5;
    for (int i = 2; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--width" && i + 1 < argc)
        width = std::stoi(argv[++i]);
      else if (arg == "--repeats" && i + 1 < argc)
        repeats = std::stoi(argv[++i]);
      else
        scene = arg;
    }
    if (mode == "rays") return pathway::benchRays(scene, width, repeats);
    if (mode == "memory") return pathway::benchMemory(scene);
    if (mode == "stages") return pathway::benchStages(scene, width, repeats);
    std::fprintf(stderr,
                 "usage: pathway_bench rays [scene] [--width W] [--repeats R]\n"
                 "       pathway_bench stages [scene] [--width W] [--repeats R]\n"
                 "       pathway_bench memory SCENE\n");
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "pathway_bench: error: %s\n", error.what());
    return 1;
  }
}
