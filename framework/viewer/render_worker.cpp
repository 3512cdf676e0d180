#include "viewer/render_worker.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/error.h"
#include "engine/recipe_builder.h"
#include "render/integrator_registry.h"
#include "scene/camera.h"
#include "viewer/render_priority.h"

namespace pathway {
namespace {

// Developing an image costs about as much as a cheap pass, so publish no more often than a
// display refreshes; the last pass before the worker rests is always published.
constexpr std::chrono::milliseconds kPublishInterval{16};

}  // namespace

bool WorkerJob::operator==(const WorkerJob& o) const {
  return scene == o.scene && lanes == o.lanes && settings == o.settings && camera == o.camera &&
         balance == o.balance && budget == o.budget;
}

struct RenderWorker::Lane {
  std::string integrator;
  std::unique_ptr<RenderSession> session;  // null when the lane could not start or failed
  std::vector<TodoRecord> todos;
  std::string error;
  bool dirty = false;      // passes done since the last publish
  bool published = false;  // this job's first image is out
  Clock::time_point lastPublish;
};

RenderWorker::RenderWorker(std::function<void()> onPublish, bool belowUi)
    : onPublish_(std::move(onPublish)), belowUi_(belowUi), thread_([this] {
        if (belowUi_) lowerThisThreadsPriority();
        run();
      }) {}

RenderWorker::~RenderWorker() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    quit_ = true;
    cancel_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

uint64_t RenderWorker::submit(WorkerJob job) {
  uint64_t id;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_ = std::move(job);
    id = ++pendingId_;
    pendingSince_ = Clock::now();
    cancel_ = true;  // the running pass stops at its next tile
  }
  idle_ = false;
  wake_.notify_all();
  return id;
}

void RenderWorker::setPaused(bool paused) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    paused_ = paused;
  }
  wake_.notify_all();
}

std::shared_ptr<const LaneFrame> RenderWorker::frame(size_t lane) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return lane < published_.size() ? published_[lane] : nullptr;
}

double RenderWorker::passSeconds() const {
  const int64_t start = passStart_.load();
  if (start == 0) return 0.0;
  return std::chrono::duration<double>(Clock::now().time_since_epoch() - Clock::duration(start))
      .count();
}

void RenderWorker::run() {
  for (;;) {
    std::optional<WorkerJob> job;
    uint64_t id = 0;
    Clock::time_point submitted;
    int next = -1;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      auto ready = [&] { return quit_ || pending_ || (!paused_ && nextLane() >= 0); };
      if (!ready()) {
        lock.unlock();
        publishPending();
        lock.lock();
        idle_ = !pending_;
        wake_.wait(lock, ready);
      }
      if (quit_) return;
      idle_ = false;
      if (pending_) {
        job = std::move(pending_);
        pending_.reset();
        id = pendingId_;
        submitted = pendingSince_;
        cancel_ = false;
      } else {
        next = nextLane();
      }
    }
    if (job)
      start(std::move(*job), id, submitted);
    else if (next >= 0)
      renderPass(static_cast<size_t>(next));
  }
}

void RenderWorker::start(WorkerJob job, uint64_t id, Clock::time_point submitted) {
  lanes_.clear();  // the old renderers go before the old scene can
  scene_ = job.scene;
  camera_ = job.camera;
  jobId_ = id;
  submittedAt_ = submitted;
  balance_ = job.balance;
  budget_ = job.budget;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    published_.resize(job.lanes.size());  // panes that just appeared show nothing stale
  }
  for (const LaneJob& laneJob : job.lanes) {
    auto lane = std::make_unique<Lane>();
    lane->integrator = laneJob.integrator;
    try {
      if (!scene_) throw PathwayError("no scene is loaded");
      RecipeBuilder builder(laneJob.integrator);
      // The panel's widgets only produce values the parameters accept; anything else is refused.
      for (const auto& [name, value] : laneJob.params) builder.param(name, value);
      RenderSettings settings = job.settings;
      if (laneJob.sampler) settings.sampler = *laneJob.sampler;
      if (laneJob.filter) settings.filter = *laneJob.filter;
      const RenderRecipe& recipe = builder.earlierStages(laneJob.earlierStages).settings(settings);
      const CameraPose& pose = job.camera;
      const Camera camera(pose.position, pose.lookAt, pose.up, pose.yfov, recipe.settings.width,
                          recipe.settings.height);
      lane->session = std::make_unique<RenderSession>(*scene_->tracer, camera, recipe);
    } catch (const std::exception& error) {
      lane->session.reset();
      lane->error = error.what();
    }
    lanes_.push_back(std::move(lane));
    if (!lanes_.back()->error.empty()) publish(lanes_.size() - 1);
  }
}

int RenderWorker::nextLane() const {
  auto measure = [this](const Lane& lane) {
    const RenderStats& stats = lane.session->renderer().stats();
    return balance_ == Balance::EqualTime ? stats.seconds
                                          : static_cast<double>(stats.counters.totalRays());
  };
  int behind = -1;
  for (size_t i = 0; i < lanes_.size(); ++i) {
    if (!lanes_[i]->session) continue;  // failed to start
    if (behind < 0 || measure(*lanes_[i]) < measure(*lanes_[behind])) behind = static_cast<int>(i);
  }
  if (behind < 0) return -1;
  const Lane& lane = *lanes_[behind];
  if (lane.session->renderer().finished()) return -1;  // the one behind cannot catch up: stop both
  if (lanes_.size() > 1 && budget_ > 0.0 && measure(lane) >= budget_) return -1;
  return behind;
}

void RenderWorker::renderPass(size_t index) {
  Lane& lane = *lanes_[index];
  bool completed = false;
  passStart_ = Clock::now().time_since_epoch().count();
  try {
    completed = lane.session->renderer().renderPass(&cancel_);
    lane.todos = lane.session->todos();
  } catch (const std::exception& error) {  // a stage that throws must not take the viewer down
    lane.error = error.what();
    lane.session.reset();
    completed = true;
  }
  passStart_ = 0;
  if (!completed) return;  // cancelled: a new job is waiting
  ++passes_;
  lane.dirty = true;
  const bool due = !lane.published || Clock::now() - lane.lastPublish >= kPublishInterval ||
                   !lane.session || lane.session->renderer().finished();
  if (due) publish(index);
}

void RenderWorker::publishPending() {
  for (size_t i = 0; i < lanes_.size(); ++i)
    if (lanes_[i]->dirty) publish(i);
}

void RenderWorker::publish(size_t index) {
  Lane& lane = *lanes_[index];
  auto frame = std::make_shared<LaneFrame>();
  frame->job = jobId_;
  frame->scenePath = scene_ ? scene_->scene.sourcePath : "";
  frame->sceneContent = scene_ ? scene_->contentHash : 0;
  frame->camera = camera_;
  frame->integrator = lane.integrator;
  frame->todos = lane.todos;
  frame->error = lane.error;
  if (lane.session) {
    const Renderer& renderer = lane.session->renderer();
    RenderResult result = lane.session->develop();
    frame->params = lane.session->recipe().params;
    frame->earlierStages = lane.session->recipe().earlierStages;
    frame->settings = renderer.settings();
    frame->stats = result.stats;
    frame->images = std::move(result.images);
    frame->unresolvedPixels = result.unresolvedPixels;
    frame->metadata = std::move(result.metadata);
    const float perSample = 1.0f / static_cast<float>(std::max(1u, frame->stats.samplesPerPixel));
    frame->raysPerSample.clear();
    for (uint64_t rays : renderer.raysPerPixel())
      frame->raysPerSample.push_back(static_cast<float>(rays) * perSample);
  }
  const Clock::time_point now = Clock::now();
  if (!lane.published)
    frame->firstImageSeconds = std::chrono::duration<double>(now - submittedAt_).count();
  else if (const auto previous = this->frame(index))
    frame->firstImageSeconds = previous->firstImageSeconds;
  lane.published = true;
  lane.dirty = false;
  lane.lastPublish = now;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (index < published_.size()) published_[index] = std::move(frame);
  }
  if (onPublish_) onPublish_();
}

}  // namespace pathway
