// Uses every function render/stage_api.h documents, once. It is linked into the program but never
// run: it keeps each of those functions in the program, and the framework symbols it needs, with
// those of the reference's stage files, are all the program exports to the stage libraries it
// loads (CMakeLists.txt, scripts/stage-exports.cmake). A stage file that calls anything else of
// the framework fails to load, naming the symbol. Keep it in step with the signature block atop
// stage_api.h.
#include "render/stage_api.h"
#include "stages/stage1.h"
#include "stages/stage2.h"
#include "stages/stage5.h"

namespace pathway {

// Two stages' shapes: one that hands functions on (stages 1 and 2), one built from its setup.
struct HandingOn : EyeLightIntegrator {};
struct FromSetup : EyeLightIntegrator {
  explicit FromSetup(const StageSetup<Stage5Params>& setup) {
    const Stage1Functions& one = setup.kit.stage1();
    const Stage2Functions& two = setup.kit.stage2();
    (void)one, (void)two, (void)setup.params.maxDepth;
  }
};

Color useEveryStageApiFunction(const Ray& ray, SampleStream& samples, const RenderContext& context,
                               FilmBlock& film, const PixelFilter& filter, const Scene& scene,
                               const EmissiveTriangle& light) {
  PATHWAY_TODO("every call below");
  const Frame frame(Vec3(0.0f, 0.0f, 1.0f));
  Color sum(maxComponent(frame.toWorld(Vec3(samples.next1D()))));
  sum += Color(samples.next2D(), static_cast<float>(samples.dimension()));
  if (const std::optional<SurfaceHit> hit = context.intersect(ray, RayKind::Primary)) {
    sum += eyeLightShading(*hit, ray) * eyeLightCosine(*hit, ray);
    sum += Color(context.occluded(hit->spawnRay(hit->normal), RayKind::Secondary) ? 1.0f : 0.0f);
    sum += Color(context.occluded(hit->spawnRayTo(light.p0, light.normal), RayKind::Shadow));
  }
  sum += context.background() + light.power();
  film.addSample(0, 0, filter.evaluate(0.5f, 0.5f) * filter.radius(), sum);
  sum *= static_cast<float>(collectEmissiveTriangles(scene).size());
  for (EmitterWeighting weighting : {EmitterWeighting::Area, EmitterWeighting::Power}) {
    const EmitterPicker picker(scene, weighting);
    if (!picker.empty()) sum *= picker.pick(0.5f).probability;
    if (const std::optional<SurfaceHit> hit = context.intersect(ray, RayKind::Secondary))
      sum *= picker.pickOf(*hit).probability;
  }
  registerStage<HandingOn>(stage1(), Stage1Functions{});
  registerStage<HandingOn>(stage2(), Stage2Functions{});
  registerStage<FromSetup>(stage5());
  return sum + EyeLightIntegrator().Li(ray, samples, context);
}

}  // namespace pathway
