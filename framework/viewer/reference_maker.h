// "Make reference" (key M): the reference of the left pane's stage at its view and settings, with
// many samples per pixel, rendered on a thread of its own (as grading does) so the panes keep
// refining. Its progress is readable at any time; cancel() stops it at the next pixel.
#pragma once

#include <atomic>
#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>

#include "viewer/loaded_scene.h"
#include "viewer/reference_image.h"
#include "viewer/render_worker.h"

namespace pathway {

class ReferenceMaker {
 public:
  ReferenceMaker() = default;
  ~ReferenceMaker();  // cancels, and waits for the thread (a pixel's worth of work)
  ReferenceMaker(const ReferenceMaker&) = delete;
  ReferenceMaker& operator=(const ReferenceMaker&) = delete;

  // Starts (cancelling a reference still rendering) for `frame`, at `spp` samples per pixel. A
  // stage without a built-in reference does not start: error() says so.
  // `belowUi`: render at a lower priority than the UI thread (render_priority.h).
  void start(std::shared_ptr<const LaneFrame> frame, std::shared_ptr<const LoadedScene> scene,
             uint32_t spp, bool belowUi = false);
  void cancel();
  bool running() const { return result_.valid(); }
  // The finished reference, once; nothing while it renders, after a failure or a cancel.
  std::optional<ReferenceImage> take();

  const std::string& integrator() const { return integrator_; }  // what it renders
  uint32_t sppDone() const { return progress_ ? progress_->spp.load() : 0; }
  uint32_t sppTarget() const { return sppTarget_; }
  const std::string& error() const { return error_; }  // why the last one failed

 private:
  struct Progress {
    std::atomic<uint32_t> spp{0};
    std::atomic<bool> cancel{false};
  };
  struct Outcome {
    std::optional<ReferenceImage> reference;
    std::string error;
  };

  std::shared_ptr<Progress> progress_;  // shared with the thread, which may outlive a cancel
  std::future<Outcome> result_;
  std::string integrator_;
  uint32_t sppTarget_ = 0;
  std::string error_;
};

}  // namespace pathway
