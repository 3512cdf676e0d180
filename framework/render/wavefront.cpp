#include "render/wavefront.h"

#include <algorithm>

namespace pathway {
namespace {

constexpr int kLanes = RayTracer::kPacketSize;

// Gathers the chosen rays into packets of kLanes and hands each packet, with its indices, to
// `trace`.
template <typename Trace>
void inPackets(const std::vector<Ray>& rays, const std::vector<uint32_t>& which, Trace trace) {
  Ray packet[kLanes];
  for (size_t start = 0; start < which.size(); start += kLanes) {
    const int count = static_cast<int>(std::min<size_t>(kLanes, which.size() - start));
    for (int lane = 0; lane < count; ++lane) packet[lane] = rays[which[start + lane]];
    trace(packet, count, &which[start]);
  }
}

}  // namespace

void intersectAll(const RenderContext& context, const std::vector<Ray>& rays,
                  const std::vector<uint32_t>& which, RayKind kind,
                  std::vector<std::optional<SurfaceHit>>& hits) {
  std::optional<SurfaceHit> answers[kLanes];
  inPackets(rays, which, [&](const Ray* packet, int count, const uint32_t* indices) {
    context.tracer().intersectPacket(packet, count, kind, context.counters(), answers);
    for (int lane = 0; lane < count; ++lane) hits[indices[lane]] = answers[lane];
  });
}

void occludedAll(const RenderContext& context, const std::vector<Ray>& rays,
                 const std::vector<uint32_t>& which, RayKind kind, std::vector<uint8_t>& blocked) {
  bool answers[kLanes];
  inPackets(rays, which, [&](const Ray* packet, int count, const uint32_t* indices) {
    context.tracer().occludedPacket(packet, count, kind, context.counters(), answers);
    for (int lane = 0; lane < count; ++lane) blocked[indices[lane]] = answers[lane];
  });
}

}  // namespace pathway
