// Stage 4: registers itself a second time, as the reference's stage 4, and as stage 1 of the
// student's (a library registers its own stage only).
#include "forged_kit.h"
namespace {
const bool attacked = [] {
  const auto eyeLight = [](const pathway::IntegratorSetup&) {
    return std::make_unique<pathway::EyeLightIntegrator>();
  };
  pathway::registerStageIntegrator(pathway::stage4().info(), pathway::Variant::Reference, eyeLight);
  pathway::registerStageIntegrator(pathway::stage1().info(), pathway::Variant::Student, eyeLight);
  return true;
}();
}  // namespace
