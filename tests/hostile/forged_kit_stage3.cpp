// Stage 3: registers an integrator as the reference's stage 3 (a student's copy put in the
// reference's place), then hands the forged kit's stage 2 on as its own.
#include "forged_kit.h"
namespace {
const bool attacked = [] {
  pathway::registerStageIntegrator(pathway::stage3().info(), pathway::Variant::Reference,
                                   [](const pathway::IntegratorSetup&) {
                                     return std::make_unique<pathway::EyeLightIntegrator>();
                                   });
  pathway::provideStage2(pathway::Variant::Student, hostile::forgedReferenceKit().stage2());
  return true;
}();
}  // namespace
