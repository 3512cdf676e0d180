#include "viewer/reference_maker.h"

#include <algorithm>
#include <chrono>
#include <exception>

#include "viewer/render_priority.h"
#include "viewer/stage_reference.h"

namespace pathway {
namespace {

// Passes of 1/128 of the target: the progress bar moves every second or so, and a pass costs
// little beyond its samples.
constexpr uint32_t kPassesForProgress = 128;

}  // namespace

ReferenceMaker::~ReferenceMaker() {
  cancel();
}

void ReferenceMaker::start(std::shared_ptr<const LaneFrame> frame,
                           std::shared_ptr<const LoadedScene> scene, uint32_t spp, bool belowUi) {
  cancel();
  error_.clear();
  sppTarget_ = spp;
  const IntegratorInfo* reference = stageReferenceOf(frame->integrator);
  integrator_ = reference ? reference->name : frame->integrator;
  if (!reference)
    error_ = missingReferenceOf(frame->integrator) + " (load one with --reference)";
  else if (!frame->error.empty() || !scene)
    error_ = "cannot make a reference: " + frame->integrator + " did not render";
  if (!error_.empty()) return;
  progress_ = std::make_shared<Progress>();
  auto progress = progress_;
  result_ = std::async(std::launch::async, [frame, scene, spp, progress, belowUi] {
    if (belowUi) lowerThisThreadsPriority();  // a thread of its own: it ends with the render
    Outcome outcome;
    try {
      const uint32_t perPass = std::max(1u, spp / kPassesForProgress);
      auto onPass = [&](const RenderStats& stats) { progress->spp = stats.samplesPerPixel; };
      std::optional<RenderResult> result =
          renderStageReference(*frame, *scene, spp, perPass, onPass, &progress->cancel);
      if (result) {
        ReferenceImage& reference = outcome.reference.emplace();
        reference.image = std::move(result->images.color);
        reference.view = viewOf(*frame);
        reference.seed = referenceSeed(frame->settings.seed);
        reference.sampler = frame->settings.sampler;
      }
    } catch (const std::exception& error) {
      outcome.error = error.what();
    }
    return outcome;
  });
}

void ReferenceMaker::cancel() {
  if (!result_.valid()) return;
  progress_->cancel = true;
  result_.wait();
  result_ = {};
}

std::optional<ReferenceImage> ReferenceMaker::take() {
  if (!result_.valid() || result_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return std::nullopt;
  Outcome outcome = result_.get();
  error_ = outcome.error;
  if (outcome.reference)
    outcome.reference->source = integrator_ + ", " + std::to_string(sppTarget_) + " spp";
  return std::move(outcome.reference);
}

}  // namespace pathway
