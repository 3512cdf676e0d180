// Measurement helpers the benchmark modes share: timers, resident memory, ray sets, the renderer's
// steady-state rate and the replay of a render's exact rays through raw Embree.
#pragma once

#include <tbb/task_arena.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "raw_embree.h"
#include "scene/ray_tracer.h"

namespace pathway {
class RenderSession;
}

namespace pathway::bench {

double secondsOf(const std::function<void()>& work);
// Best of `repeats` runs: the least disturbed by other processes on a shared machine.
double bestSeconds(int repeats, const std::function<void()>& work);

long residentBytes();  // of this process, from /proc/self/statm
// The one-minute load average: how busy the shared machine is (this process's threads count too).
double loadAverage();

Vec3 cosineDirection(const Vec3& normal, float u1, float u2);

// Camera rays through jittered pixel positions, and from their hits cosine-distributed rays.
struct RaySets {
  std::vector<Ray> primary;
  std::vector<Ray> incoherent;
};
RaySets makeRays(const Scene& scene, const RayTracer& tracer, int width, int height);

using Params = std::map<std::string, std::string>;

// One render kept ready to time one pass at a time: `spp` samples per pixel per pass on `threads`
// worker threads (0: all cores), after a warm-up pass (first touch of the film and tile memory).
// Timing pass by pass lets measurements interleave, so that on a shared machine the things
// compared see the same load, and the best of each is taken from the same quiet moments.
class PassTimer {
 public:
  PassTimer(const Scene& scene, const RayTracer& tracer, const std::string& name,
            const Params& params, int width, uint32_t spp, int passes, int threads = 0);
  ~PassTimer();
  double timePass();                                     // seconds
  uint64_t raysPerPass() const { return raysPerPass_; }  // exact, the same every pass

 private:
  std::unique_ptr<RenderSession> session_;
  uint64_t raysPerPass_ = 0;
};

// The renderer's steady-state rate: the best of `repeats` passes of a PassTimer on all cores.
double rendererSeconds(const Scene& scene, const RayTracer& tracer, const std::string& name,
                       const Params& params, int width, uint32_t spp, int repeats,
                       uint64_t* raysPerPass);

// Every ray one pass of the stage traces, recorded from a single-threaded render.
std::vector<LoggedRay> recordRays(const Scene& scene, RayTracer& tracer, const std::string& name,
                                  const Params& params, int width, uint32_t spp);

// Replays `log` through raw Embree, in parallel on `threads` threads (0: all cores).
class ReplayTimer {
 public:
  ReplayTimer(const RawEmbree& raw, const std::vector<LoggedRay>& log, int threads = 0);
  double timeReplay();  // seconds

 private:
  const RawEmbree& raw_;
  const std::vector<LoggedRay>& log_;
  std::vector<char> sink_;
  tbb::task_arena arena_;
};

// The best of `repeats` replays on all cores.
double replaySeconds(const RawEmbree& raw, const std::vector<LoggedRay>& log, int repeats);

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
