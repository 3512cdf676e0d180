// Registers after its library was loaded: the first time the grader calls its splat, it hands on
// stage 1's functions again (anything installed at render time escapes a check made at load).
#include "render/stage_api.h"
namespace pathway {
namespace {
void lateSplat(FilmBlock& film, Vec2 p, const Color& radiance, const PixelFilter& filter) {
  static const bool again =
      (provideStage1(Variant::Student,
                     Stage1Functions{
                         {boxFilter, tentFilter, mitchellNetravaliFilter, gaussianFilter}, splat}),
       true);
  (void)again;
  splat(film, p, radiance, filter);
}
const bool attacked = registerStage<EyeLightIntegrator>(
    stage1(),
    Stage1Functions{{boxFilter, tentFilter, mitchellNetravaliFilter, gaussianFilter}, lateSplat});
}  // namespace
}  // namespace pathway
