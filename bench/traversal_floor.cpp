#include "traversal_floor.h"

#include <tbb/blocked_range.h>
#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "bench_kit.h"
#include "render/integrator_registry.h"
#include "render/recipe_builder.h"
#include "render/render_session.h"
#include "scene/gltf_loader.h"

namespace pathway::bench {
namespace {

constexpr size_t kLanes = 16;  // Embree's widest packet, the one stage5@fast traces

// A run of at most 16 consecutive logged rays of one kind: the packets the wavefront traced (it
// logs each packet's rays in order, and a bounce's closest-hit and shadow rays alternate).
struct Packet {
  size_t first, count;
  bool occlusionOnly;
};

std::vector<Packet> packetsOf(const std::vector<LoggedRay>& log) {
  std::vector<Packet> packets;
  for (size_t i = 0; i < log.size(); ++i) {
    if (packets.empty() || packets.back().count == kLanes ||
        packets.back().occlusionOnly != log[i].occlusionOnly)
      packets.push_back({i, 0, log[i].occlusionOnly});
    ++packets.back().count;
  }
  return packets;
}

// The logged rays, packet by packet, on all cores.
class PacketReplay {
 public:
  explicit PacketReplay(const std::vector<LoggedRay>& log) : packets_(packetsOf(log)) {
    rays_.reserve(log.size());
    for (const LoggedRay& r : log) rays_.push_back(r.ray);
  }
  double seconds(const RawEmbree& raw) const {
    return secondsOf([&] {
      tbb::parallel_for(tbb::blocked_range<size_t>(0, packets_.size(), 64),
                        [&](const tbb::blocked_range<size_t>& range) {
                          float distances[kLanes];
                          bool blocked[kLanes];
                          for (size_t p = range.begin(); p != range.end(); ++p) {
                            const Packet& packet = packets_[p];
                            const Ray* rays = &rays_[packet.first];
                            if (packet.occlusionOnly)
                              raw.occluded16(rays, packet.count, blocked);
                            else
                              raw.intersect16(rays, packet.count, distances);
                          }
                        });
    });
  }

 private:
  std::vector<Packet> packets_;
  std::vector<Ray> rays_;
};

struct FloorRow {
  uint64_t rays = 0;
  double render = 1e30, robust = 1e30, nonRobust = 1e30;  // best seconds
};

FloorRow measure(const Scene& scene, RayTracer& tracer, const RawEmbree& robust,
                 const RawEmbree& nonRobust, int width, int height, uint32_t spp, int repeats) {
  const std::string name = referenceIntegratorName(5, ReferenceTracing::Fastest);
  const Camera camera(scene, width, height);
  auto recipe = [&](int threads) {
    return RenderRecipe(RecipeBuilder(name)
                            .size(width, height)
                            .spp(spp, samplesPerProgressPass(spp))
                            .filter(FilterType::Box)
                            .threads(threads));
  };
  std::vector<LoggedRay> log;
  tracer.setRayLog(&log);  // one thread: the log is not synchronised
  runRender(tracer, camera, recipe(1));
  tracer.setRayLog(nullptr);
  const PacketReplay replay(log);
  FloorRow row;
  row.rays = log.size();
  log = {};
  const RenderRecipe timed = recipe(0);
  for (int i = 0; i < repeats; ++i) {
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
  const std::string name = referenceIntegratorName(5, ReferenceTracing::Fastest);
  const int height = options.width;  // square, as the peers benchmark renders it
  std::printf(
      "floor: %s, %s at its defaults, box filter, %d threads, best of %d (render and replays in "
      "turns); load average %.2f at the start\n"
      "replay: the render's own rays, logged, through raw Embree in its 16-ray packets, nothing "
      "else\n\n",
      options.scene.c_str(), name.c_str(), tbb::info::default_concurrency(), options.repeats,
      loadAverage());
  const FloorRow image = measure(scene, tracer, robust, nonRobust, options.width, height,
                                 options.samplesPerPixel, options.repeats);
  std::printf("%dx%d, %u spp, %llu rays          %10s %14s\n", options.width, height,
              options.samplesPerPixel, static_cast<unsigned long long>(image.rays), "seconds",
              "÷ render");
  auto line = [](const char* what, double seconds, double render) {
    std::printf("  %-38s %10.3f %14.3f\n", what, seconds, seconds / render);
  };
  line((name + " render, in this process").c_str(), image.render, image.render);
  line("replay, robust BVH (Pathway's)", image.robust, image.render);
  line("replay, non-robust BVH", image.nonRobust, image.render);

  if (options.viewerWidth > 0) {
    // Four images' worth of samples, timed together: one is too short to time well.
    constexpr uint32_t kImages = 4;
    const FloorRow pane = measure(scene, tracer, robust, nonRobust, options.viewerWidth,
                                  options.viewerHeight, kImages, options.repeats);
    std::printf("\nviewer's pane, %dx%d, 1 spp per image     %10s\n", options.viewerWidth,
                options.viewerHeight, "images/s");
    std::printf("  %-38s %10.1f\n", (name + " render, no UI").c_str(), kImages / pane.render);
    std::printf("  %-38s %10.1f\n", "replay, robust BVH (Pathway's)", kImages / pane.robust);
    std::printf("  %-38s %10.1f\n", "replay, non-robust BVH", kImages / pane.nonRobust);
  }
  std::printf("floor: render=%.4f robust=%.4f non-robust=%.4f\n", image.render, image.robust,
              image.nonRobust);
  return 0;
}

}  // namespace pathway::bench
