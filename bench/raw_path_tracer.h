// A minimal path tracer straight on Embree 3: the ceiling `pathway_bench ceiling` holds stage5@ref
// against. It computes the same estimator as stage 5 with its defaults (one NEE shadow ray per hit
// to a point on an emitter picked by area, one cosine-weighted continuation, Russian roulette
// after rr-depth, max-depth bounces, emission seen by camera rays only, box filter one pixel wide)
// on the same scene and camera, with none of the framework's render machinery in between: no
// RayTracer, RenderContext, Renderer or Film. Whatever the framework spends beyond this tracer is
// overhead that a faster framework could remove.
//
// It writes stage 5's estimator a second time on purpose (the one exception to one estimator per
// stage): calling the stage's code would put the framework's machinery back in between, and the
// ceiling would measure nothing. `pathway_bench ceiling` fails when the two images' means
// disagree, so the copy cannot drift from stage 5 unnoticed.
//
// Its random numbers come from one PCG32 per pixel, or (`sobol`) are stage 5's default numbers:
// the framework's Owen-scrambled Sobol' sampler, drawn in the order stage 5 draws them, so the
// two tracers compute the same estimator with the same numbers and the only difference left is
// the machinery.
#pragma once

#include <cstdint>
#include <vector>

#include "core/ray_counters.h"
#include "raw_embree.h"
#include "render/emitter_picker.h"
#include "scene/camera.h"

namespace pathway::bench {

struct RawPathSettings {
  int width = 256;
  int height = 256;
  uint32_t samplesPerPixel = 64;
  int maxDepth = 5;       // stage 5's max-depth: most bounces (-1: no limit)
  int rouletteDepth = 3;  // stage 5's rr-depth: bounces before Russian roulette starts
  uint64_t seed = 0;
  bool sobol = false;  // the framework's Owen-scrambled Sobol' numbers instead of PCG32
};

struct RawPathImage {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  // mean radiance per pixel, rows top to bottom
  RayCounters rays;           // primary, secondary and shadow rays traced, exactly
};

class RawPathTracer {
 public:
  // `embree` must hold `scene`'s meshes with geometry IDs equal to the mesh indices (RawEmbree
  // does). Textures are not looked up: albedo is the material's base colour.
  RawPathTracer(const Scene& scene, const RawEmbree& embree);

  RawPathImage render(const Camera& camera, const RawPathSettings& settings) const;

 private:
  // What shading needs of a mesh, gathered once so that a hit costs one small lookup.
  struct MeshShading {
    Color albedo;
    Color emission;  // zero unless the material emits
    bool doubleSided;
  };

  // `Numbers` gives next1D() and next2D(), as the framework's SampleStream does.
  template <typename Numbers>
  Color radiance(const Ray& cameraRay, const RawPathSettings& settings, Numbers& numbers,
                 RayCounters& rays) const;
  // `leaving`: the hit point already moved off its surface to the side of `normal`.
  template <typename Numbers>
  Color directLight(const Vec3& position, const Vec3& leaving, const Vec3& normal,
                    const Color& albedo, Numbers& numbers, RayCounters& rays) const;

  const Scene& scene_;
  RTCScene embree_;
  std::vector<MeshShading> meshes_;
  EmitterPicker lights_;
};

}  // namespace pathway::bench
