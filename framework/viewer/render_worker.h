// The viewer's background render thread. It owns the renderers and runs their passes one after
// the other, publishing a developed image after each; the UI thread only swaps in the newest image
// (a shared_ptr under a mutex), so drawing never waits for rendering. submit() describes what to
// render; a different job cancels the running pass through the renderer's atomic flag and starts
// over at once: the renderer checks the flag at every pixel, so even a long pass stops promptly.
//
// Split view: a job has one lane per pane. The lanes never run at the same time: the one behind
// (in render time, or in rays traced) gets the next pass, so both sides stay at equal time or
// equal ray count, within one pass.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/todo.h"
#include "engine/render_session.h"
#include "io/image_io.h"
#include "viewer/loaded_scene.h"
#include "viewer/orbit_camera.h"

namespace pathway {

struct LaneJob {
  std::string integrator;                // registry name, "stage2" or "stage2@ref"
  std::map<std::string, double> params;  // by name; missing ones take their declared default
  EarlierStages earlierStages = EarlierStages::Own;
  // This lane's own sampler and pixel filter; none: the job's settings'.
  std::optional<SamplerType> sampler = std::nullopt;
  std::optional<FilterType> filter = std::nullopt;

  bool operator==(const LaneJob& o) const {
    return integrator == o.integrator && params == o.params && earlierStages == o.earlierStages &&
           sampler == o.sampler && filter == o.filter;
  }
};

enum class Balance { EqualTime, EqualRays };

struct WorkerJob {
  std::shared_ptr<const LoadedScene> scene;
  std::vector<LaneJob> lanes;  // one, or two for the split view
  RenderSettings settings;     // shared by the lanes; width x height is each lane's image
  CameraPose camera;
  Balance balance = Balance::EqualTime;
  double budget =
      0.0;  // split view: seconds or rays per lane (by balance); 0: up to the spp target

  bool operator==(const WorkerJob& o) const;
  bool operator!=(const WorkerJob& o) const { return !(*this == o); }
};

// One lane's image after a pass, with everything the panel shows about it.
struct LaneFrame {
  uint64_t job = 0;  // the submit() it belongs to
  std::string scenePath;
  uint64_t sceneContent = 0;  // LoadedScene::contentHash: the lights' size changes it
  CameraPose camera;
  std::string integrator;
  ParamValues params;  // the values used, every declared parameter
  EarlierStages earlierStages = EarlierStages::Own;
  RenderSettings settings;
  FilmImages images;                 // developed colour, variance, Σw
  std::vector<float> raysPerSample;  // per pixel, rows top to bottom
  size_t unresolvedPixels = 0;
  RenderStats stats;
  double firstImageSeconds = 0.0;  // from submit() to this job's first image of this lane
  std::vector<TodoRecord> todos;   // unfinished stage code this lane ran
  std::string error;               // the lane could not render (refused parameters, ...)
  RenderMetadata metadata;         // what `pathway render` writes with its images
};

class RenderWorker {
 public:
  // `onPublish` runs on the worker thread after each new frame (e.g. to wake the UI's event loop).
  // `belowUi`: render at a lower priority than the UI thread (render_priority.h).
  explicit RenderWorker(std::function<void()> onPublish = {}, bool belowUi = false);
  ~RenderWorker();
  RenderWorker(const RenderWorker&) = delete;
  RenderWorker& operator=(const RenderWorker&) = delete;

  // Replaces the current job (cancelling its pass) and returns the new job's id.
  uint64_t submit(WorkerJob job);
  void setPaused(bool paused);

  // The newest frame of `lane`; it may still belong to an earlier job while a new one starts.
  std::shared_ptr<const LaneFrame> frame(size_t lane) const;
  // True when the current job has nothing left to do (finished, over budget, failed or paused).
  bool idle() const { return idle_.load(); }
  // Seconds the pass now running has taken so far (0 when none runs): slow passes stay visible.
  double passSeconds() const;
  uint64_t passesDone() const { return passes_.load(); }

 private:
  using Clock = std::chrono::steady_clock;
  struct Lane;

  void run();
  void start(WorkerJob job, uint64_t id, Clock::time_point submitted);
  int nextLane() const;
  void renderPass(size_t index);
  void publish(size_t index);
  void publishPending();

  std::function<void()> onPublish_;
  bool belowUi_ = false;
  std::atomic<bool> cancel_{false};
  std::atomic<bool> idle_{true};
  std::atomic<uint64_t> passes_{0};
  std::atomic<int64_t> passStart_{0};  // Clock ticks; 0: no pass running

  mutable std::mutex mutex_;  // guards the members below
  std::condition_variable wake_;
  std::optional<WorkerJob> pending_;
  uint64_t pendingId_ = 0;
  Clock::time_point pendingSince_;
  bool paused_ = false;
  bool quit_ = false;
  std::vector<std::shared_ptr<const LaneFrame>> published_;

  // The worker thread's own state.
  std::vector<std::unique_ptr<Lane>> lanes_;
  std::shared_ptr<const LoadedScene> scene_;
  CameraPose camera_;
  uint64_t jobId_ = 0;
  Clock::time_point submittedAt_;
  Balance balance_ = Balance::EqualTime;
  double budget_ = 0.0;

  std::thread thread_;  // last: starts after everything above exists
};

}  // namespace pathway
