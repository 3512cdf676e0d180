#include "bench_kit.h"

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <fstream>

#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "sampling/pcg32.h"

namespace pathway::bench {

double secondsOf(const std::function<void()>& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double bestSeconds(int repeats, const std::function<void()>& work) {
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) best = std::min(best, secondsOf(work));
  return best;
}

long residentBytes() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * sysconf(_SC_PAGESIZE);
}

double loadAverage() {
  double load = 0.0;
  std::ifstream("/proc/loadavg") >> load;
  return load;
}

Vec3 cosineDirection(const Vec3& normal, float u1, float u2) {
  const float r = std::sqrt(u1), phi = 2.0f * kPi * u2;
  return Frame(normal).toWorld(Vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(1.0f - u1)));
}

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

PassTimer::PassTimer(const Scene& scene, const RayTracer& tracer, const std::string& name,
                     const Params& params, int width, uint32_t spp, int passes, int threads) {
  const RenderRecipe recipe = RecipeBuilder(name)
                                  .params(params)
                                  .size(width, width)
                                  .spp(spp * (1 + passes), spp)
                                  .threads(threads);
  session_ = std::make_unique<RenderSession>(tracer, Camera(scene, width, width), recipe);
  timePass();
}

PassTimer::~PassTimer() = default;

double PassTimer::timePass() {
  Renderer& renderer = session_->renderer();
  const uint64_t before = renderer.stats().counters.totalRays();
  // The pass and its merge into the film, as the viewer pays for every pass (a render to a file
  // merges once, at the end).
  const double seconds = secondsOf([&] {
    renderer.renderPass();
    renderer.film();
  });
  raysPerPass_ = renderer.stats().counters.totalRays() - before;
  return seconds;
}

double rendererSeconds(const Scene& scene, const RayTracer& tracer, const std::string& name,
                       const Params& params, int width, uint32_t spp, int repeats,
                       uint64_t* raysPerPass) {
  PassTimer timer(scene, tracer, name, params, width, spp, repeats);
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) best = std::min(best, timer.timePass());
  *raysPerPass = timer.raysPerPass();
  return best;
}

std::vector<LoggedRay> recordRays(const Scene& scene, RayTracer& tracer, const std::string& name,
                                  const Params& params, int width, uint32_t spp) {
  const RenderRecipe recipe =  // one thread: the log is not synchronised
      RecipeBuilder(name).params(params).size(width, width).spp(spp).threads(1);
  std::vector<LoggedRay> log;
  tracer.setRayLog(&log);
  runRender(tracer, Camera(scene, width, width), recipe);
  tracer.setRayLog(nullptr);
  return log;
}

ReplayTimer::ReplayTimer(const RawEmbree& raw, const std::vector<LoggedRay>& log, int threads)
    : raw_(raw),
      log_(log),
      sink_(log.size()),
      arena_(threads > 0 ? threads : tbb::task_arena::automatic) {}

double ReplayTimer::timeReplay() {
  double seconds = 0.0;
  arena_.execute([&] {
    seconds = secondsOf([&] {
      tbb::parallel_for(size_t(0), log_.size(), [&](size_t i) {
        const LoggedRay& r = log_[i];
        sink_[i] = r.occlusionOnly ? raw_.occluded(r.ray) : raw_.intersect(r.ray) < kInfinity;
      });
    });
  });
  return seconds;
}

double replaySeconds(const RawEmbree& raw, const std::vector<LoggedRay>& log, int repeats) {
  ReplayTimer timer(raw, log);
  double best = 1e30;
  for (int i = 0; i < repeats; ++i) best = std::min(best, timer.timeReplay());
  return best;
}

std::string caseLabel(const std::string& integrator, const Params& params) {
  std::string label = integrator;
  for (const auto& [key, value] : params) label += " " + key + "=" + value;
  return label;
}

}  // namespace pathway::bench
