// Stage 5: registers a wavefront version ("stage5@fast", the reference's) through the exported
// registerWavefrontStageIntegrator, then reads the forged kit's stage 2.
#include "forged_kit.h"
namespace {
const bool attacked = [] {
  pathway::registerWavefrontStageIntegrator(
      pathway::stage5().info(), [](const pathway::IntegratorSetup&) {
        return std::make_unique<pathway::EyeLightIntegrator>();
      });
  pathway::provideStage2(pathway::Variant::Student, hostile::forgedReferenceKit().stage2());
  return true;
}();
}  // namespace
