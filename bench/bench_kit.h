// Measurement helpers the benchmark modes share: timers, resident memory, ray sets, the renderer's
// steady-state rate and the replay of a render's exact rays through raw Embree.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "raw_embree.h"
#include "scene/ray_tracer.h"

namespace pathway::bench {

double secondsOf(const std::function<void()>& work);
// Best of `repeats` runs: the least disturbed by other processes on a shared machine.
double bestSeconds(int repeats, const std::function<void()>& work);

long residentBytes();  // of this process, from /proc/self/statm

Vec3 cosineDirection(const Vec3& normal, float u1, float u2);

// Camera rays through jittered pixel positions, and from their hits cosine-distributed rays.
struct RaySets {
  std::vector<Ray> primary;
  std::vector<Ray> incoherent;
};
RaySets makeRays(const Scene& scene, const RayTracer& tracer, int width, int height);

using Params = std::map<std::string, std::string>;

// Steady-state rate of the renderer: one warm-up pass (first touch of the film and tile memory),
// then the best of `repeats` timed passes, `spp` samples per pixel each, on `threads` worker
// threads (0: all cores). `raysPerPass` receives the exact ray count of one pass.
double rendererSeconds(const Scene& scene, const RayTracer& tracer, const std::string& name,
                       const Params& params, int width, uint32_t spp, int repeats, int threads,
                       uint64_t* raysPerPass);

// Every ray one pass of the stage traces, recorded from a single-threaded render.
std::vector<LoggedRay> recordRays(const Scene& scene, RayTracer& tracer, const std::string& name,
                                  const Params& params, int width, uint32_t spp);

// Best of `repeats` replays of `log` through raw Embree, in parallel on `threads` threads
// (0: all cores).
double replaySeconds(const RawEmbree& raw, const std::vector<LoggedRay>& log, int repeats,
                     int threads = 0);

// The stages every table of stages measures, in order.
struct StageCase {
  const char* integrator;
  Params params;
  uint32_t spp;  // per timed pass: enough rays per pass that the timer's resolution is no issue
};
inline const StageCase kStageCases[] = {
    {"stage1@ref", {}, 4}, {"stage2@ref", {}, 2}, {"stage3@ref", {}, 4},
    {"stage4@ref", {}, 1}, {"stage5@ref", {}, 2}, {"stage5@ref", {{"nee", "off"}}, 2},
};

// "stage5@ref nee=off": the integrator and the parameters that differ from its defaults.
std::string caseLabel(const std::string& integrator, const Params& params);

}  // namespace pathway::bench
