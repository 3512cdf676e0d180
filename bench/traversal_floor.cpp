#include "traversal_floor.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <vector>

#include "bench_kit.h"
#include "core/error.h"
#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "render/integrator_registry.h"
#include "scene/gltf_loader.h"

namespace pathway::bench {
namespace {

constexpr int kLanes = RayTracer::kPacketSize;
// The log holds 32 bytes a ray (stage 5 traces about 4.5 a sample) and the replay a copy of 28:
// a bigger image should be measured at fewer samples per pixel, which does not change the rates.
constexpr uint64_t kMostSamples = uint64_t(1) << 23;  // twice the peers image's 256 x 256 x 64

// One query as the render made it: a packet of up to 16 rays of one kind, or a single ray.
struct Packet {
  size_t first, count;
  bool occlusionOnly;
};

std::vector<Packet> packetsOf(const std::vector<LoggedRay>& log) {
  std::vector<Packet> packets;
  for (size_t i = 0; i < log.size(); ++i) {
    if (packets.empty() || log[i].startsPacket || packets.back().count == size_t(kLanes))
      packets.push_back({i, 0, log[i].occlusionOnly});
    ++packets.back().count;
  }
  return packets;
}

// What a replay found: closest-hit rays that hit something, shadow rays that were blocked.
struct Answers {
  uint64_t hits = 0, blocked = 0;
  bool operator==(const Answers& o) const { return hits == o.hits && blocked == o.blocked; }
};

// The logged rays, query by query, on all cores.
class PacketReplay {
 public:
  explicit PacketReplay(const std::vector<LoggedRay>& log) : packets_(packetsOf(log)) {
    rays_.reserve(log.size());
    for (const LoggedRay& r : log) rays_.push_back(r.ray);
  }
  size_t rays() const { return rays_.size(); }

  double seconds(const RawEmbree& raw) const {
    return secondsOf([&] { trace(raw); });
  }
  // The same replay, counting its answers (untimed: the counting is not traversal).
  Answers answers(const RawEmbree& raw) const { return trace(raw); }
  // Each ray on its own through rtcIntersect1/rtcOccluded1, to check the packets against.
  Answers singleRayAnswers(const RawEmbree& raw) const {
    std::atomic<uint64_t> hits{0}, blocked{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, packets_.size(), 64), [&](const auto& range) {
      uint64_t h = 0, b = 0;
      for (size_t p = range.begin(); p != range.end(); ++p)
        for (size_t i = packets_[p].first; i < packets_[p].first + packets_[p].count; ++i)
          packets_[p].occlusionOnly ? b += raw.occluded(rays_[i])
                                    : h += raw.intersect(rays_[i]) < kInfinity;
      hits += h, blocked += b;
    });
    return {hits, blocked};
  }

 private:
  Answers trace(const RawEmbree& raw) const {
    std::atomic<uint64_t> hits{0}, blocked{0};
    tbb::parallel_for(tbb::blocked_range<size_t>(0, packets_.size(), 64), [&](const auto& range) {
      float distances[kLanes];
      bool occluded[kLanes];
      uint64_t h = 0, b = 0;
      for (size_t p = range.begin(); p != range.end(); ++p) {
        const Packet& packet = packets_[p];
        const Ray* rays = &rays_[packet.first];
        if (packet.occlusionOnly) {
          raw.occluded16(rays, packet.count, occluded);
          b += std::count(occluded, occluded + packet.count, true);
        } else {
          raw.intersect16(rays, packet.count, distances);
          h += packet.count - std::count(distances, distances + packet.count, kInfinity);
        }
      }
      hits += h, blocked += b;  // once per range: keeps the atomics out of the timed loop
    });
    return {hits, blocked};
  }

  std::vector<Packet> packets_;
  std::vector<Ray> rays_;
};

struct FloorRow {
  uint64_t rays = 0;
  double render = 1e30, robust = 1e30, nonRobust = 1e30;  // best seconds
};

FloorRow measure(const Scene& scene, RayTracer& tracer, const RawEmbree& robust,
                 const RawEmbree& nonRobust, const std::string& name, int width, int height,
                 uint32_t spp, int repeats) {
  const Camera camera(scene, width, height);
  auto recipe = [&](int threads) {
    return RenderRecipe(RecipeBuilder(name)
                            .size(width, height)
                            .spp(spp, samplesPerProgressPass(spp))
                            .filter(FilterType::Box)
                            .threads(threads));
  };
  const RenderRecipe timed = recipe(0);
  const uint64_t samples = uint64_t(width) * uint64_t(height) * spp;
  if (samples > kMostSamples)
    throw PathwayError(std::to_string(width) + "x" + std::to_string(height) + " at " +
                       std::to_string(spp) + " spp is " + std::to_string(samples) +
                       " samples; the floor logs every ray of at most " +
                       std::to_string(kMostSamples) + ": use a smaller --width or --spp");
  FloorRow row;
  // The first render counts the rays, so that the log is allocated once.
  row.render =
      secondsOf([&] { row.rays = runRender(tracer, camera, timed).stats.counters.totalRays(); });
  std::vector<LoggedRay> log;
  log.reserve(row.rays);
  tracer.setRayLog(&log);  // a one-thread render of the same image: the log is not synchronised
  runRender(tracer, camera, recipe(1));
  tracer.setRayLog(nullptr);
  const PacketReplay replay(log);
  log = {};
  if (replay.rays() != row.rays)
    throw PathwayError("the logged render traced " + std::to_string(replay.rays()) +
                       " rays, the timed one " + std::to_string(row.rays));
  // The packets must find what single rays find, or the replay is not these rays' traversal.
  const Answers packets = replay.answers(robust), single = replay.singleRayAnswers(robust);
  if (!(packets == single))
    throw PathwayError("the replayed packets found " + std::to_string(packets.hits) + " hits and " +
                       std::to_string(packets.blocked) + " blocked shadow rays, single rays " +
                       std::to_string(single.hits) + " and " + std::to_string(single.blocked));
  for (int i = 0; i < repeats; ++i) {
    if (i > 0)
      row.render = std::min(row.render, secondsOf([&] { runRender(tracer, camera, timed); }));
    row.robust = std::min(row.robust, replay.seconds(robust));
    row.nonRobust = std::min(row.nonRobust, replay.seconds(nonRobust));
  }
  return row;
}

}  // namespace

int benchFloor(const FloorOptions& options) {
  const Scene scene = loadScene(options.scene);
  RayTracer tracer(scene);
  const RawEmbree robust(scene), nonRobust(scene, RTC_SCENE_FLAG_NONE);
  const int height = options.width;  // square, as the peers benchmark renders it
  std::printf(
      "floor: %s, stageN@fast at its defaults, box filter, %d threads, best of %d (render and "
      "replays in turns); load average %.2f at the start\n"
      "replay: the rays of a one-thread render of the same image, logged, through raw Embree in "
      "the render's own packets, nothing else (checked: the packets find what single rays "
      "find)\n\n",
      options.scene.c_str(), tbb::info::default_concurrency(), options.repeats, loadAverage());
  std::printf("%dx%d, %u spp            %12s %10s %10s %10s %12s %12s\n", options.width, height,
              options.samplesPerPixel, "rays", "render s", "robust s", "non-rob. s", "÷ robust",
              "÷ non-rob.");
  FloorRow stage5;
  for (int stage : {2, 3, 5}) {
    const std::string name = referenceIntegratorName(stage, ReferenceTracing::Fastest);
    const FloorRow row = measure(scene, tracer, robust, nonRobust, name, options.width, height,
                                 options.samplesPerPixel, options.repeats);
    std::printf("  %-26s %12llu %10.3f %10.3f %10.3f %12.2f %12.2f\n", (name + " render").c_str(),
                static_cast<unsigned long long>(row.rays), row.render, row.robust, row.nonRobust,
                row.render / row.robust, row.render / row.nonRobust);
    std::fflush(stdout);
    if (stage == 5) stage5 = row;
  }

  // Four images' worth of samples, timed together: one is too short to time well.
  constexpr uint32_t kImages = 4;
  std::printf("\nviewer's pane, %dx%d, 1 spp per image   %10s %10s %10s\n", options.viewerWidth,
              options.viewerHeight, "render", "robust", "non-rob.");
  for (int stage : {3, 5}) {
    const std::string name = referenceIntegratorName(stage, ReferenceTracing::Fastest);
    const FloorRow pane = measure(scene, tracer, robust, nonRobust, name, options.viewerWidth,
                                  options.viewerHeight, kImages, options.repeats);
    std::printf("  %-26s images/s %10.1f %10.1f %10.1f\n", name.c_str(), kImages / pane.render,
                kImages / pane.robust, kImages / pane.nonRobust);
    std::fflush(stdout);
  }
  std::printf("floor: render=%.4f robust=%.4f non-robust=%.4f\n", stage5.render, stage5.robust,
              stage5.nonRobust);
  return 0;
}

}  // namespace pathway::bench
