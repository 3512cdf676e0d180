#include "viewer/viewer_app.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>

#include "core/error.h"
#include "viewer/frame_metadata.h"
#include "viewer/reference_cache.h"
#include "viewer/shortcuts.h"
#include "viewer/stage_reference.h"

namespace pathway {
namespace {

// A path under the working folder as one would type it there ("scenes/cornell_box.gltf"), so the
// Scene field (and a screenshot of it) shows no machine's folders; others stay as they are.
std::string pathAsTyped(const std::string& path) {
  std::error_code error;
  const std::filesystem::path relative =
      std::filesystem::path(path).lexically_proximate(std::filesystem::current_path(error));
  if (error || relative.empty() || *relative.begin() == "..") return path;
  return relative.string();
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void setUpImGui() {
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // the layout is fixed; no imgui.ini in the user's folder
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.Colors[ImGuiCol_WindowBg].w = 1.0f;  // an opaque panel reads better over renders
  style.WindowRounding = 0.0f;
  style.ItemSpacing.y = 3.0f;  // more of the panel fits without scrolling
  style.FramePadding.y = 2.0f;
  // A proportional font reads better than ImGui's built-in bitmap font, when the system has it.
  const char* font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
  if (std::filesystem::exists(font)) io.Fonts->AddFontFromFileTTF(font, 15.0f);
}

}  // namespace

Viewer::Viewer(std::unique_ptr<Platform> platform, ViewerState state,
               std::shared_ptr<const LoadedScene> scene)
    : platform_(std::move(platform)), state_(std::move(state)), scene_(std::move(scene)) {
  setUpImGui();
  try {
    platform_->initImGui();
  } catch (...) {
    ImGui::DestroyContext();
    throw;
  }
  for (auto& texture : textures_) texture = std::make_unique<GlTexture>(platform_->gl());
  gradeTexture_ = std::make_unique<GlTexture>(platform_->gl());
  if (scene_) {
    camera_ = OrbitCamera(scene_->scene);
    text_.sceneInput = pathAsTyped(scene_->scene.sourcePath);
  }
  Platform* wakePlatform = platform_.get();
  worker_ = std::make_unique<RenderWorker>([wakePlatform] { wakePlatform->wake(); },
                                           state_.renderBelowUi);
  fpsWindowStart_ = now();
}

Viewer::~Viewer() {
  worker_.reset();  // no more wake-ups, no more frames
  if (grading_.valid()) grading_.wait();
  for (auto& texture : textures_) texture.reset();
  gradeTexture_.reset();
  platform_->shutdownImGui();
  ImGui::DestroyContext();
}

void Viewer::pollSceneLoad() {
  if (!loading_.valid() || loading_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  try {
    scene_ = loading_.get();
    if (!loadingKeepsCamera_) camera_ = OrbitCamera(scene_->scene);
    text_.sceneFailed = false;
    text_.sceneMessage = "loaded " + std::to_string(scene_->scene.triangleCount()) + " triangles";
    for (const std::string& warning : scene_->scene.warnings) text_.sceneMessage += "\n" + warning;
  } catch (const std::exception& error) {  // a bad file is reported, never fatal
    text_.sceneFailed = true;
    text_.sceneMessage = error.what();
  }
  if (resizeLightsNext_ && scene_) startSceneLoad(scene_->scene.sourcePath, true);
  resizeLightsNext_ = false;
}

void Viewer::resizeLights() {
  // A drag moves the slider every frame: one load at a time, the newest size last.
  if (loading_.valid())
    resizeLightsNext_ = true;
  else if (scene_)
    startSceneLoad(scene_->scene.sourcePath, true);
}

void Viewer::startSceneLoad(const std::string& path, bool keepCamera) {
  text_.sceneMessage = "loading " + path + "...";
  text_.sceneFailed = false;
  loadingKeepsCamera_ = keepCamera;
  // Loading and building the BVH can take a while for big scenes: not on the UI thread.
  const SceneLoadOptions load = state_.sceneOptions;
  loading_ = std::async(std::launch::async, [path, load] { return LoadedScene::load(path, load); });
}

void Viewer::submitIfChanged(const ImageLayout& layout) {
  if (!scene_) return;
  WorkerJob job = makeJob(state_, scene_, camera_.pose(), layout.renderWidth, layout.renderHeight);
  if (submitted_ && *submitted_ == job) return;
  submitted_ = job;
  std::string integrators[2];
  for (size_t lane = 0; lane < job.lanes.size() && lane < 2; ++lane)
    integrators[lane] = job.lanes[lane].integrator;
  jobId_ = worker_->submit(std::move(job));
  // The plot follows the panes now asked for: V or B must not leave the old job's series up.
  for (int lane = 0; lane < 2; ++lane) errors_[lane].restart(jobId_, integrators[lane]);
}

bool Viewer::panesCurrent() const {
  for (int lane = 0; lane < (state_.split ? 2 : 1); ++lane) {
    const auto frame = worker_->frame(lane);
    if (!frame || frame->job != jobId_) return false;
  }
  return jobId_ != 0;
}

float Viewer::sharedScale(const std::shared_ptr<const LaneFrame>* frames) {
  if (state_.display == DisplayMode::Color) return 0.0f;
  if (state_.scaleTop > 0.0f) return state_.scaleTop;
  // Side by side, the false-colour modes share one scale: with one each, a pane with 1e-7 times
  // the other's variance would look just as noisy.
  if (!state_.split) return 0.0f;
  // Worked out again only when a pane has a new image or the display changed.
  if (frames[0] == topOf_[0] && frames[1] == topOf_[1] && topMode_ == state_.display)
    return sharedTop_;
  const LaneFrame* const shown[2] = {frames[0].get(), frames[1].get()};
  sharedTop_ = sharedScaleTop(shown, 2, state_.display);
  topOf_[0] = frames[0];
  topOf_[1] = frames[1];
  topMode_ = state_.display;
  return sharedTop_;
}

void Viewer::updateTextures() {
  const std::shared_ptr<const LaneFrame> frames[2] = {worker_->frame(0), worker_->frame(1)};
  const float scale = sharedScale(frames);
  for (int lane = 0; lane < 2; ++lane) {
    const std::shared_ptr<const LaneFrame>& frame = frames[lane];
    // Uploaded only when something shown changed: an upload costs the UI thread milliseconds.
    const bool stale = frame != shown_[lane] || shownMode_[lane] != state_.display ||
                       shownExposure_[lane] != state_.exposure || shownScale_[lane] != scale;
    if (!frame || !stale) {
      shown_[lane] = frame;
      continue;
    }
    if (!frame->images.color.pixels.empty()) {
      const DisplayImage image = makeDisplayImage(*frame, state_.display, state_.exposure, scale);
      textures_[lane]->upload(image);
      scaleMax_[lane] = image.scaleMax;
      if (frame != shown_[lane]) ++imagesShown_;
    }
    shown_[lane] = frame;
    shownMode_[lane] = state_.display;
    shownExposure_[lane] = state_.exposure;
    shownScale_[lane] = scale;
  }
}

void Viewer::toggleGrade() {
  if (grading_.valid()) return;                                      // one at a time
  const std::shared_ptr<const LaneFrame> frame = worker_->frame(0);  // the newest image
  if (grade_ && frame && grade_->job == frame->job && grade_->spp == frame->stats.samplesPerPixel) {
    grade_.reset();  // G again on the same image: hide
    return;
  }  // otherwise grade the newest image (the render may have refined since)
  grade_.reset();
  if (!frame || !scene_) return;
  if (!canGradeFrame(*frame)) {
    FrameGrade unavailable;
    unavailable.job = frame->job;
    unavailable.error = frame->error.empty()
                            ? "cannot grade: " + missingReferenceOf(frame->integrator)
                            : "cannot grade " + frame->integrator + ": it did not render";
    grade_ = unavailable;
    return;
  }
  std::shared_ptr<const LoadedScene> scene = scene_;
  grading_ = std::async(std::launch::async, [frame, scene] { return gradeFrame(*frame, *scene); });
}

void Viewer::pollGrade() {
  if (!grading_.valid() || grading_.wait_for(std::chrono::seconds(0)) != std::future_status::ready)
    return;
  grade_ = grading_.get();
  if (!grade_->heatmap.pixels.empty()) gradeTexture_->upload(displayImageOf(grade_->heatmap));
}

void Viewer::setReference(ReferenceImage reference) {
  reference_ = std::move(reference);
  for (ErrorHistory& history : errors_) history.clear();
  submitted_.reset();  // the same job again, as a new one: measured from its first pass
}

void Viewer::toggleMakeReference() {
  if (maker_.running()) {
    maker_.cancel();
    return;
  }
  const std::shared_ptr<const LaneFrame> frame = worker_->frame(0);  // the view the panes show
  if (!frame || !scene_) return;
  if (state_.cacheReferences && frame->error.empty())
    if (std::optional<ReferenceImage> cached =
            loadCachedReference(referenceCacheFolder(), *frame, *scene_, state_.referenceSpp)) {
      setReference(std::move(*cached));
      return;
    }
  referenceFor_ = frame;
  maker_.start(frame, scene_, state_.referenceSpp, state_.renderBelowUi);
}

// Measures each pane's new image against the reference, on the UI thread: imageError takes less
// than making the display image of the same frame (measured: 0.6 ms against 1.8 ms at 512 x 512,
// 9 ms against 12 ms at 1540 x 1000).
void Viewer::updateErrors() {
  if (std::optional<ReferenceImage> made = maker_.take()) {
    if (state_.cacheReferences && referenceFor_) {
      try {
        storeCachedReference(referenceCacheFolder(), *referenceFor_, *scene_, maker_.sppTarget(),
                             *made);
      } catch (const PathwayError& error) {  // the plot works without: say so, and go on
        std::fprintf(stderr, "pathway view: the reference is not kept: %s\n", error.what());
      }
    }
    setReference(std::move(*made));
  }
  if (!reference_) return;
  for (int lane = 0; lane < (state_.split ? 2 : 1); ++lane) {
    if (!shown_[lane] || shown_[lane] == measured_[lane]) continue;
    measured_[lane] = shown_[lane];
    errors_[lane].add(*shown_[lane], *reference_);
  }
}

void Viewer::saveImages(const std::string& extension) {
  text_.saveFailed = false;
  text_.saveMessage.clear();
  try {
    for (int lane = 0; lane < (state_.split ? 2 : 1); ++lane) {
      const LaneFrame* frame = shown_[lane].get();
      if (!frame || frame->images.color.pixels.empty()) throw PathwayError("nothing rendered yet");
      const std::string path =
          text_.savePrefix + (state_.split ? (lane == 0 ? "-left" : "-right") : "") + extension;
      writeImageFile(path, frame->images, frameMetadata(*frame), state_.exposure);
      text_.saveMessage += (text_.saveMessage.empty() ? "wrote " : ", ") + path;
    }
  } catch (const std::exception& error) {
    text_.saveFailed = true;
    text_.saveMessage = error.what();
  }
}

void Viewer::noteInput() {
  const ImGuiIO& io = ImGui::GetIO();
  bool input = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
               io.InputQueueCharacters.Size > 0;
  for (bool down : io.MouseDown) input = input || down;
  for (bool down : io.KeysDown) input = input || down;
  if (input) lastInput_ = now();
}

void Viewer::frame(const std::string& screenshotPath) {
  platform_->newFrame();
  ImGui::NewFrame();
  noteInput();
  pollSceneLoad();

  const std::vector<KeyPress> presses = platform_->takeKeyPresses();
  if (!presses.empty()) lastInput_ = now();
  const ShortcutEffects keys = handleShortcuts(state_, presses);
  if (keys.resetCamera) camera_.reset();
  if (keys.grade) toggleGrade();
  if (keys.makeReference) toggleMakeReference();
  if (keys.resizeLights) resizeLights();
  pollGrade();
  if (keys.screenshot) pendingScreenshot_ = text_.savePrefix + "_screenshot.png";

  updateTextures();  // before the panel, so panel and panes show the same image
  updateErrors();
  PanelStatus status;
  for (int lane = 0; lane < 2; ++lane) {
    status.frames[lane] = shown_[lane];
    status.scaleMax[lane] = scaleMax_[lane];
    status.errors[lane] = &errors_[lane];
  }
  status.reference.source = reference_ ? reference_->source : "";
  status.reference.making = maker_.running();
  status.reference.makingIntegrator = maker_.integrator();
  status.reference.sppDone = maker_.sppDone();
  status.reference.sppTarget = maker_.sppTarget();
  status.reference.error = maker_.error();
  status.idle = worker_->idle();
  status.passSeconds = worker_->passSeconds();
  status.uiFramesPerSecond = fps_;
  status.sceneLoading = loading_.valid();
  status.fixedSize = state_.fixedWidth > 0;
  switch (drawPanel(state_, text_, status)) {
    case PanelAction::OpenScene:
      startSceneLoad(text_.sceneInput, false);
      break;
    case PanelAction::ResizeLights:
      resizeLights();
      break;
    case PanelAction::SaveExr:
      saveImages(".exr");
      break;
    case PanelAction::SavePng:
      saveImages(".png");
      break;
    case PanelAction::Screenshot:
      pendingScreenshot_ = text_.savePrefix + "_screenshot.png";
      break;
    case PanelAction::ResetCamera:
      camera_.reset();
      break;
    case PanelAction::Grade:
      toggleGrade();
      break;
    case PanelAction::MakeReference:
      toggleMakeReference();
      break;
    case PanelAction::None:
      break;
  }
  worker_->setPaused(state_.paused);

  const ImageLayout layout = layoutPanes(state_, kPanelWidth);
  mouse_.update(layout, camera_);
  submitIfChanged(layout);
  for (int lane = 0; lane < layout.count; ++lane) {
    PaneInfo info;
    info.frame = shown_[lane].get();
    info.mode = state_.display;
    info.scaleMax = scaleMax_[lane];
    if (layout.count == 2) info.side = lane == 0 ? "left" : "right";
    if (lane == 0 && grading_.valid()) info.gradeLines = {"grading against the reference..."};
    if (lane == 0 && grade_ && shown_[0] && grade_->job == shown_[0]->job) {
      if (!grade_->error.empty()) {
        info.gradeLines = {grade_->error};
      } else {
        const bool refined = grade_->spp != shown_[0]->stats.samplesPerPixel;
        info.gradeLines = {grade_->summary, refined
                                                ? "(the image has refined since: G grades it again)"
                                                : "(G hides this)"};
        info.gradePassed = grade_->passed;
        if (!grade_->heatmap.pixels.empty()) info.gradeOverlay = gradeTexture_.get();
      }
    }
    drawPane(layout.panes[lane], *textures_[lane], info);
  }
  drawHelp(state_);
  ImGui::Render();

  int width = 0, height = 0;
  platform_->framebufferSize(width, height);
  const GlFunctions& gl = platform_->gl();
  gl.Viewport(0, 0, width, height);
  gl.ClearColor(0.12f, 0.12f, 0.13f, 1.0f);
  gl.Clear(GL_COLOR_BUFFER_BIT);
  platform_->renderDrawData(ImGui::GetDrawData());

  // Read back before present(): after a swap the back buffer's content is undefined.
  const std::string shot = screenshotPath.empty() ? pendingScreenshot_ : screenshotPath;
  pendingScreenshot_.clear();
  if (!shot.empty()) {
    try {
      writeScreenshot(shot, width, height, readFramebuffer(gl, width, height));
      text_.saveFailed = false;
      text_.saveMessage = "wrote " + shot;
    } catch (const PathwayError& error) {
      if (!screenshotPath.empty()) throw;  // asked for on the command line: fail the command
      text_.saveFailed = true;
      text_.saveMessage = error.what();
    }
  }
  platform_->present();

  ++fpsFrames_;
  const double t = now();
  if (t - fpsWindowStart_ >= 1.0) {
    fps_ = static_cast<float>(fpsFrames_ / (t - fpsWindowStart_));
    fpsWindowStart_ = t;
    fpsFrames_ = 0;
  }
}

void Viewer::waitForChange(bool asWindow) {
  // Right after input ImGui needs a few frames (hover, popups, text cursor); otherwise a new
  // image wakes the loop (the worker calls Platform::wake) and the timeout keeps the counters of
  // a slow pass moving. Offscreen there is no input to wait for: frames come at display rate.
  const bool interacting = now() - lastInput_ < 0.5 || (!platform_->interactive() && !asWindow);
  platform_->waitEvents(interacting ? 1.0 / 60.0 : 0.25);
}

}  // namespace pathway
