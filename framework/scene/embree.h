// Embree as Pathway uses it: the one file that knows which Embree the build found. Debian 12
// ships Embree 3.13 and Debian 13 Embree 4.3. They agree on devices, scenes, geometry and the ray
// and hit layouts; they differ in how a query is called: Embree 3 takes an RTCIntersectContext
// that each query initialises, Embree 4 takes optional RTCIntersectArguments in its place. Both
// defaults are the same query (incoherent rays, no filter functions), so the two give the same
// hits. Everything that traces through Embree calls these four functions.
#pragma once

#if PATHWAY_EMBREE_MAJOR == 4
#include <embree4/rtcore.h>
#elif PATHWAY_EMBREE_MAJOR == 3
#include <embree3/rtcore.h>
#else
#error "PATHWAY_EMBREE_MAJOR must be 3 or 4: CMakeLists.txt sets it from the Embree it finds"
#endif

#include <cstddef>

namespace pathway {

// Scenes with at least this many triangles get Embree's compact BVH (less memory, slower rays).
constexpr size_t kCompactBvhFromTriangles = 100000;
// The Embree scene flags RayTracer builds with for a scene of `triangles` triangles.
RTCSceneFlags bvhFlags(size_t triangles);

namespace embree {

#if PATHWAY_EMBREE_MAJOR == 4

inline void intersect1(RTCScene scene, RTCRayHit& rayHit) {
  rtcIntersect1(scene, &rayHit);
}
inline void occluded1(RTCScene scene, RTCRay& ray) {
  rtcOccluded1(scene, &ray);
}
// `valid`: -1 for a lane that holds a ray, 0 for one that does not.
inline void intersect16(const int* valid, RTCScene scene, RTCRayHit16& packet) {
  rtcIntersect16(valid, scene, &packet);
}
inline void occluded16(const int* valid, RTCScene scene, RTCRay16& packet) {
  rtcOccluded16(valid, scene, &packet);
}

#else

inline RTCIntersectContext defaultContext() {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  return context;
}
inline void intersect1(RTCScene scene, RTCRayHit& rayHit) {
  RTCIntersectContext context = defaultContext();
  rtcIntersect1(scene, &context, &rayHit);
}
inline void occluded1(RTCScene scene, RTCRay& ray) {
  RTCIntersectContext context = defaultContext();
  rtcOccluded1(scene, &context, &ray);
}
inline void intersect16(const int* valid, RTCScene scene, RTCRayHit16& packet) {
  RTCIntersectContext context = defaultContext();
  rtcIntersect16(valid, scene, &context, &packet);
}
inline void occluded16(const int* valid, RTCScene scene, RTCRay16& packet) {
  RTCIntersectContext context = defaultContext();
  rtcOccluded16(valid, scene, &context, &packet);
}

#endif

}  // namespace embree
}  // namespace pathway
