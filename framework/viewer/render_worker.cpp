#include "viewer/render_worker.h"

#include <algorithm>
#include <cmath>
#include <exception>

#include "core/error.h"
#include "film/pixel_filter.h"
#include "render/integrator_registry.h"
#include "scene/camera.h"

namespace pathway {
namespace {

// Developing an image costs about as much as a cheap pass, so publish no more often than a
// display refreshes; the last pass before the worker rests is always published.
constexpr std::chrono::milliseconds kPublishInterval{16};

bool sameSettings(const RenderSettings& a, const RenderSettings& b) {
  return a.width == b.width && a.height == b.height && a.samplesPerPixel == b.samplesPerPixel &&
         a.samplesPerPass == b.samplesPerPass && a.sampler == b.sampler && a.seed == b.seed &&
         a.threads == b.threads && a.filter == b.filter && a.filterRadius == b.filterRadius &&
         a.tileSize == b.tileSize;
}

void mergeTodos(std::vector<TodoRecord>& into, const std::vector<TodoRecord>& hit) {
  for (const TodoRecord& todo : hit) {
    const bool known = std::any_of(into.begin(), into.end(), [&](const TodoRecord& t) {
      return t.file == todo.file && t.line == todo.line;
    });
    if (!known) into.push_back(todo);
  }
}

}  // namespace

bool WorkerJob::operator==(const WorkerJob& o) const {
  return scene == o.scene && lanes == o.lanes && sameSettings(settings, o.settings) &&
         camera == o.camera && balance == o.balance && budget == o.budget;
}

struct RenderWorker::Lane {
  std::string integrator;
  std::map<std::string, double> params;
  // The renderer refers to the camera and the integrators, so a Lane never moves (unique_ptr).
  std::unique_ptr<Integrator> integratorObject;
  std::unique_ptr<Camera> camera;
  std::unique_ptr<Renderer> renderer;
  std::vector<TodoRecord> todos;
  std::string error;
  bool dirty = false;      // passes done since the last publish
  bool published = false;  // this job's first image is out
  Clock::time_point lastPublish;
};

RenderWorker::RenderWorker(std::function<void()> onPublish)
    : onPublish_(std::move(onPublish)), thread_([this] { run(); }) {}

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
      const IntegratorInfo& info = findIntegrator(laneJob.integrator);
      ParamValues values;
      for (const ParamSpec& spec : info.params) {
        const auto given = laneJob.params.find(spec.name);
        double value = given != laneJob.params.end() ? given->second : spec.defaultValue;
        value = std::clamp(value, spec.minValue, spec.maxValue);
        if (spec.isInteger) value = std::round(value);
        values.set(spec.name, value);
        lane->params[spec.name] = value;
      }
      clearTodosHit();
      lane->integratorObject = info.create(values, scene_->scene);
      const RenderSettings& s = job.settings;
      const CameraPose& pose = job.camera;
      lane->camera = std::make_unique<Camera>(pose.position, pose.lookAt, pose.up, pose.yfov,
                                              s.width, s.height);
      lane->renderer =
          std::make_unique<Renderer>(*scene_->tracer, *lane->camera, *lane->integratorObject,
                                     filterFunctions(info.variant), s);
      mergeTodos(lane->todos, todosHit());
    } catch (const std::exception& error) {
      lane->renderer.reset();
      lane->error = error.what();
    }
    lanes_.push_back(std::move(lane));
    if (!lanes_.back()->error.empty()) publish(lanes_.size() - 1);
  }
}

int RenderWorker::nextLane() const {
  auto measure = [this](const Lane& lane) {
    const RenderStats& stats = lane.renderer->stats();
    return balance_ == Balance::EqualTime ? stats.seconds
                                          : static_cast<double>(stats.counters.totalRays());
  };
  int behind = -1;
  for (size_t i = 0; i < lanes_.size(); ++i) {
    if (!lanes_[i]->renderer) continue;  // failed to start
    if (behind < 0 || measure(*lanes_[i]) < measure(*lanes_[behind])) behind = static_cast<int>(i);
  }
  if (behind < 0) return -1;
  const Lane& lane = *lanes_[behind];
  if (lane.renderer->finished()) return -1;  // the one behind cannot catch up: stop both
  if (lanes_.size() > 1 && budget_ > 0.0 && measure(lane) >= budget_) return -1;
  return behind;
}

void RenderWorker::renderPass(size_t index) {
  Lane& lane = *lanes_[index];
  bool completed = false;
  passStart_ = Clock::now().time_since_epoch().count();
  try {
    clearTodosHit();
    completed = lane.renderer->renderPass(&cancel_);
    mergeTodos(lane.todos, todosHit());
  } catch (const std::exception& error) {  // a stage that throws must not take the viewer down
    lane.error = error.what();
    lane.renderer.reset();
    completed = true;
  }
  passStart_ = 0;
  if (!completed) return;  // cancelled: a new job is waiting
  ++passes_;
  lane.dirty = true;
  const bool due = !lane.published || Clock::now() - lane.lastPublish >= kPublishInterval ||
                   !lane.renderer || lane.renderer->finished();
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
  frame->camera = camera_;
  frame->integrator = lane.integrator;
  frame->params = lane.params;
  frame->todos = lane.todos;
  frame->error = lane.error;
  if (lane.renderer) {
    const Renderer& renderer = *lane.renderer;
    const Film& film = renderer.film();
    frame->settings = renderer.settings();
    frame->stats = renderer.stats();
    frame->images.color = film.develop(&frame->unresolvedPixels);
    frame->images.variance = film.variance();
    frame->images.weight = film.weights();
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
