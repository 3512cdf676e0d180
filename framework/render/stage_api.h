// Everything a stage file (assignments/ and solutions/) uses, in one include. What a stage may
// call, with the signatures of the framework headers it comes from (no need to open them; the
// test StageApi.SignatureBlockMatchesTheHeaders checks this block against them):
//
// Small maths (core/math.h). Vec2, Vec3, Color are glm::vec2 / vec3 / vec3 (glm::dot,
// glm::normalize work on them); constants kPi, kInvPi, kInfinity.
//   float maxComponent(const Vec3& v);
//   struct Ray { Vec3 origin; Vec3 direction; float tMax = kInfinity; };  // the segment (0, tMax],
//       in units of |direction| (it need not be unit length)
//   struct Frame {  // orthonormal basis around a unit normal: local z = normal
//     Vec3 tangent, bitangent, normal;
//     explicit Frame(const Vec3& n);
//     Vec3 toWorld(const Vec3& local) const;
//   };
//
// The interface a stage implements (render/integrator.h), and its ray queries:
//   class Integrator {
//     virtual Color Li(const Ray& cameraRay, SampleStream& samples,
//                      const RenderContext& context) const = 0;
//   };
//   class RenderContext {  // every query counts its ray, by kind
//     // The closest hit along `ray` in (0, tMax], or std::nullopt.
//     std::optional<SurfaceHit> intersect(const Ray& ray, RayKind kind) const;
//     // Whether anything blocks `ray` in (0, tMax] (cheaper: it stops at the first blocker).
//     bool occluded(const Ray& ray, RayKind kind) const;
//     const Color& background() const;  // radiance of rays that leave the scene
//   };
//   // Primary: the camera ray. Secondary: AO rays and bounce rays. Shadow: rays to a light.
//   enum class RayKind { Primary, Secondary, Shadow };
//
// What a hit reports (scene/surface_hit.h):
//   struct SurfaceHit {
//     float distance;   // ray parameter t of the hit
//     Vec3 position;
//     Vec3 normal;      // unit geometric normal, turned to face the incoming ray
//     bool frontFace;   // the ray hit the counter-clockwise (front) side
//     Color albedo;     // Lambertian reflectance ρ (the BRDF is ρ/π)
//     Color emitted;    // radiance emitted back along the ray (zero on a one-sided back face)
//     uint32_t mesh, triangle;
//     // A ray from this point in `direction` (any length; tMax in units of |direction|), its
//     // origin moved off the surface so it cannot hit it:
//     Ray spawnRay(const Vec3& direction, float tMax = kInfinity) const;
//     // A shadow ray from this point to `target` on a surface with normal `targetNormal`; both
//     // ends are moved off their surfaces, the segment is (0, 1]:
//     Ray spawnRayTo(const Vec3& target, const Vec3& targetNormal) const;
//   };
//
// A sample's random numbers (sampling/sampler.h), values in [0, 1), handed out in a fixed order;
// dimensions 0-1 are already taken by the renderer for the pixel position:
//   class SampleStream {
//     float next1D();              // the next dimension
//     Vec2 next2D();               // the next two; starts on an even dimension (may skip one)
//     uint32_t dimension() const;  // the dimension the next call hands out (or skips)
//   };
//
// What a stage is built from (render/stage_definition.h, render/stage_kit.h): its constructor
// takes `const StageSetup<StageNParams>& setup`, with
//   setup.params: the stage's typed parameters, declared beside it in framework/stages/stageN.h
//                 (e.g. setup.params.aoDistance; a misspelt name does not compile);
//   setup.kit:    const Stage1Functions& stage1() const; const Stage2Functions& stage2() const;
//   setup.scene:  const Scene& scene (for EmitterPicker).
//   struct FilterProfiles {
//     float (*box)(float x);
//     float (*tent)(float x);
//     float (*mitchellNetravali)(float x);
//     float (*gaussian)(float x, float sigma);
//   };
//   struct Stage1Functions {
//     FilterProfiles profiles;
//     void (*splat)(FilmBlock& film, Vec2 position, const Color& radiance,
//                   const PixelFilter& filter);
//   };
//   struct Stage2Functions {
//     Vec3 (*sampleCosineHemisphere)(Vec2 u);       // local direction, density cos θ / π
//     float (*cosineHemispherePdf)(float cosTheta);  // that density, per unit solid angle
//     float (*ambientOcclusionSample)(const RenderContext& context, const SurfaceHit& hit, Vec2 u,
//                                     float distance);  // V·cos θ / (π·pdf)
//   };
//   struct Stage5Functions {  // for the warp test (`pathway warptest --stage 5`)
//     LightSample (*sampleLight)(const EmitterPicker& lights, float uPick, Vec2 uPoint);
//   };
// Stage 1's film and filter (film/film.h, film/pixel_filter.h):
//   void FilmBlock::addSample(int x, int y, float weight, const Color& radiance);  // Σ w·L, Σ w
//   float PixelFilter::radius() const;                  // f is 0 when |dx| or |dy| exceeds it
//   float PixelFilter::evaluate(float dx, float dy) const;  // f(dx)·f(dy)
//
// Picking an emitter for next-event estimation (render/emitter_picker.h, scene/emitters.h):
//   enum class EmitterWeighting { Area, Power };  // stage 5's params.lightPick
//   class EmitterPicker {
//     EmitterPicker(const Scene& scene, EmitterWeighting weighting);
//     struct Pick { const EmissiveTriangle* emitter; float probability; };  // of this triangle
//     bool empty() const;        // no emitter can emit power
//     Pick pick(float u) const;  // u in [0, 1); not to be called when empty()
//     // The triangle `hit` lies on as pick() chooses it ({nullptr, 0}: it emits nothing), for
//     // multiple importance sampling of light a bounce ray found:
//     Pick pickOf(const SurfaceHit& hit) const;
//   };
//   struct EmissiveTriangle {
//     Vec3 p0, p1, p2;
//     Vec3 normal;       // unit, on the front (counter-clockwise) side
//     float area;
//     Color emission;    // radiance leaving the front face (and the back, if doubleSided)
//     bool doubleSided;
//     uint32_t mesh, triangle;
//     Color power() const;  // emission · π · area, per emitting side
//   };
//   // Every emitting triangle of the scene (what EmitterPicker picks from):
//   std::vector<EmissiveTriangle> collectEmissiveTriangles(const Scene& scene);
//   struct LightSample {  // what a stage's light sampling returns
//     Vec3 position;
//     Vec3 normal;                                // the emitter's front-face normal
//     const EmissiveTriangle* emitter = nullptr;
//     float pdfArea = 0.0f;                       // density of this point per unit area
//   };
//
// The framework's placeholder picture, a light at the eye (render/eye_light_integrator.h):
//   float eyeLightCosine(const SurfaceHit& hit, const Ray& ray);   // |cos θ| to the ray
//   Color eyeLightShading(const SurfaceHit& hit, const Ray& ray);  // albedo·|cos θ| + emitted
//   class EyeLightIntegrator;  // an Integrator that returns eyeLightShading (stage 1's shading)
//
// Marking and registering (core/todo.h and below):
//   PATHWAY_TODO("what to write");  // a statement: records that it ran (the stage is unfinished)
//                                   // and prints its file and line once; it never stops
//   // `stage`: the stage's declaration, stageN() from framework/stages/stageN.h
//   template <typename IntegratorType> bool registerStage(const StageDefinition<P>& stage);
//   template <typename IntegratorType> bool registerStage(const StageDefinition<P>& stage,
//                                                         const Stage1Functions& handedOn);
//   template <typename IntegratorType> bool registerStage(const StageDefinition<P>& stage,
//                                                         const Stage2Functions& handedOn);
//   template <typename IntegratorType> bool registerStage(const StageDefinition<P>& stage,
//                                                         const Stage5Functions& handedOn);
//
// Stage 4's ray budget is checked by the framework before rendering starts.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

#include "core/math.h"
#include "core/todo.h"
#include "core/variant.h"
#include "film/film.h"
#include "film/pixel_filter.h"
#include "render/emitter_picker.h"
#include "render/eye_light_integrator.h"
#include "render/integrator.h"
#include "render/integrator_registry.h"
#include "render/stage_definition.h"
#include "render/stage_kit.h"

#if defined(PATHWAY_VARIANT_REFERENCE)
#define PATHWAY_THIS_VARIANT ::pathway::Variant::Reference
#elif defined(PATHWAY_VARIANT_STUDENT)
#define PATHWAY_THIS_VARIANT ::pathway::Variant::Student
#else
#error "stage files are compiled as part of pathway_stages_student or pathway_stages_reference"
#endif

namespace pathway {
// Internal linkage: every stage file gets its own copy, which knows the variant it is built for.
namespace {

// Registers `IntegratorType` as stage `stage` of the variant being compiled ("stage3" in
// assignments/, "stage3@ref" in solutions/), under the name, summary and parameters the stage
// declares (framework/stages/stageN.h). The integrator is built from a StageSetup<Params> (its
// typed parameters, the kit, the scene), or from nothing if it needs none.
template <typename IntegratorType, typename Params>
bool registerStage(const StageDefinition<Params>& stage) {
  return registerStageIntegrator(
      stage.info(), PATHWAY_THIS_VARIANT,
      [&stage](const IntegratorSetup& setup) -> std::unique_ptr<Integrator> {
        if constexpr (std::is_constructible_v<IntegratorType, const StageSetup<Params>&>) {
          const Params params = stage.read(setup.params);
          return std::make_unique<IntegratorType>(
              StageSetup<Params>{params, setup.kit, setup.scene});
        } else {
          return (void)setup, std::make_unique<IntegratorType>();
        }
      });
}

// The same, for the stages that hand functions on (stages 1 and 2 to the later ones, stage 5 to
// the warp test).
template <typename IntegratorType, typename Params>
bool registerStage(const StageDefinition<Params>& stage, const Stage1Functions& handedOn) {
  provideStage1(PATHWAY_THIS_VARIANT, handedOn);
  return registerStage<IntegratorType>(stage);
}
template <typename IntegratorType, typename Params>
bool registerStage(const StageDefinition<Params>& stage, const Stage2Functions& handedOn) {
  provideStage2(PATHWAY_THIS_VARIANT, handedOn);
  return registerStage<IntegratorType>(stage);
}
template <typename IntegratorType, typename Params>
bool registerStage(const StageDefinition<Params>& stage, const Stage5Functions& handedOn) {
  provideStage5(PATHWAY_THIS_VARIANT, handedOn);
  return registerStage<IntegratorType>(stage);
}

}  // namespace
}  // namespace pathway
