// Everything a stage file (assignments/ and solutions/) uses, in one include:
//   - Integrator, RenderContext: the interface a stage implements, and its ray queries
//     (context.intersect / context.occluded, which count themselves);
//   - SurfaceHit: position, normal, albedo, emission, and hit.spawnRay / hit.spawnRayTo;
//   - SampleStream: next1D() / next2D(), the sample's dimensions in a fixed order;
//   - Frame, Vec2/Vec3/Color, kPi: small maths;
//   - StageKit: the earlier stages' functions (kit.stage1(), kit.stage2());
//   - EmitterPicker, LightSample: picking an emitter for next-event estimation (stage 5);
//   - eyeLightShading: the framework's placeholder picture;
//   - PATHWAY_TODO and registerStage.
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
      stage.number, PATHWAY_THIS_VARIANT,
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

// The same, for the stages that hand functions on to the later ones (stages 1 and 2).
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

}  // namespace
}  // namespace pathway
