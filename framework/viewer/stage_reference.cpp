#include "viewer/stage_reference.h"

#include "core/error.h"
#include "engine/recipe_builder.h"
#include "stage_loading/reference_library.h"

namespace pathway {

uint64_t referenceSeed(uint64_t seed) {
  return kReferenceSeed + seed;
}

const IntegratorInfo* stageReferenceOf(const std::string& integrator) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == integrator)
      return info->stage > 0 && findStageIntegrator(info->stage, Variant::Reference)
                 ? &findIntegrator(referenceIntegratorName(info->stage, ReferenceTracing::Fastest))
                 : nullptr;
  return nullptr;
}

std::string missingReferenceOf(const std::string& integrator) {
  for (const IntegratorInfo* info : allIntegrators())
    if (info->name == integrator && info->stage > 0)
      return "no reference of " + integrator + " here: " + referenceStageMissing(info->stage);
  return "no reference of " + integrator + ": it is not a course stage";
}

std::optional<RenderResult> renderStageReference(
    const LaneFrame& frame, const LoadedScene& scene, uint32_t spp, uint32_t samplesPerPass,
    const std::function<void(const RenderStats&)>& onPass, const std::atomic<bool>* cancel) {
  const IntegratorInfo* reference = stageReferenceOf(frame.integrator);
  if (!reference) throw PathwayError(missingReferenceOf(frame.integrator));
  // The stage's parameters are declared once, for both variants.
  const RenderRecipe recipe = RecipeBuilder(*reference)
                                  .params(frame.params)
                                  .settings(frame.settings)
                                  .spp(spp, samplesPerPass)
                                  .seed(referenceSeed(frame.settings.seed));
  const CameraPose& pose = frame.camera;
  const Camera camera(pose.position, pose.lookAt, pose.up, pose.yfov, recipe.settings.width,
                      recipe.settings.height);
  RenderSession session(*scene.tracer, camera, recipe);
  if (!session.renderer().renderAll(onPass, cancel)) return std::nullopt;
  return session.develop();
}

}  // namespace pathway
