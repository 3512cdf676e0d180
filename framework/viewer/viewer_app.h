// `pathway view`: the interactive viewer. One Viewer draws frames (panel + panes) into whatever
// Platform it is given; the render worker fills the panes in the background.
#pragma once

#include <cstdint>
#include <future>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "viewer/error_plot.h"
#include "viewer/frame_grade.h"
#include "viewer/gl_display.h"
#include "viewer/image_view.h"
#include "viewer/initial_state.h"
#include "viewer/panel.h"
#include "viewer/platform.h"
#include "viewer/reference_image.h"
#include "viewer/reference_maker.h"
#include "viewer/render_worker.h"
#include "viewer/viewer_options.h"
#include "viewer/viewer_state.h"

namespace pathway {

class Viewer {
 public:
  Viewer(std::unique_ptr<Platform> platform, ViewerState state,
         std::shared_ptr<const LoadedScene> scene);
  ~Viewer();

  // Draws one frame; when `screenshotPath` is set, also writes it (throws PathwayError).
  void frame(const std::string& screenshotPath = "");
  // Sleeps until something may have changed (input, a new image) or a short timeout. Offscreen
  // frames come at display rate, unless `asWindow` paces them as a window without input would be.
  void waitForChange(bool asWindow = false);
  bool shouldClose() const { return platform_->shouldClose(); }
  // Every pane shows an image (or an error) of the job now submitted.
  bool panesCurrent() const;
  const RenderWorker& worker() const { return *worker_; }
  // Grades the left pane's image against the reference (G); again while shown: hides it.
  void toggleGrade();
  // True while a grade is being made.
  bool grading() const { return grading_.valid(); }
  uint64_t imagesShown() const { return imagesShown_; }
  // The error plot's reference (from --reference); the panes start over to be measured from 1 spp.
  void setReference(ReferenceImage reference);
  // Makes the left pane's reference in the background (M); again while it renders: cancels it.
  void toggleMakeReference();
  bool makingReference() const { return maker_.running(); }
  bool hasReference() const { return reference_.has_value(); }
  std::string referenceSource() const { return reference_ ? reference_->source : ""; }
  const ErrorHistory& errors(int lane) const { return errors_[lane]; }

 private:
  void pollSceneLoad();
  // Loads `path` with the state's scene options beside the UI thread (pollSceneLoad takes it).
  void startSceneLoad(const std::string& path, bool keepCamera);
  // The scene again, its lights at the state's size, seen from where the camera is.
  void resizeLights();
  void submitIfChanged(const ImageLayout& layout);
  // The split view's one false-colour scale for these frames (0: each pane its own).
  float sharedScale(const std::shared_ptr<const LaneFrame>* frames);
  void updateTextures();
  void saveImages(const std::string& extension);
  void pollGrade();
  void updateErrors();
  void noteInput();

  std::unique_ptr<Platform> platform_;
  ViewerState state_;
  PanelText text_;
  std::shared_ptr<const LoadedScene> scene_;
  std::future<std::shared_ptr<const LoadedScene>> loading_;
  bool loadingKeepsCamera_ = false;  // the same scene with its lights resized: same view
  bool resizeLightsNext_ = false;    // the light size moved during a load: load again after it
  OrbitCamera camera_;
  CameraMouse mouse_;
  std::unique_ptr<GlTexture> textures_[2];
  std::unique_ptr<GlTexture> gradeTexture_;
  std::future<FrameGrade> grading_;
  std::optional<FrameGrade> grade_;  // shown while its frame's job is the left pane's
  ReferenceMaker maker_;
  std::shared_ptr<const LaneFrame> referenceFor_;  // the view maker_ renders, to cache it by
  std::optional<ReferenceImage> reference_;
  ErrorHistory errors_[2];
  std::shared_ptr<const LaneFrame> measured_[2];  // the newest image each history has seen
  std::shared_ptr<const LaneFrame> shown_[2];
  DisplayMode shownMode_[2] = {DisplayMode::Color, DisplayMode::Color};
  float shownExposure_[2] = {0.0f, 0.0f};
  float scaleMax_[2] = {0.0f, 0.0f};
  float shownScale_[2] = {0.0f, 0.0f};  // the shared scale each texture was made with (0: own)
  // Both panes' shared false-colour top (sharedScaleTop), for the frames and mode it is of.
  std::shared_ptr<const LaneFrame> topOf_[2];
  DisplayMode topMode_ = DisplayMode::Color;
  float sharedTop_ = 0.0f;
  std::unique_ptr<RenderWorker> worker_;
  std::optional<WorkerJob> submitted_;
  uint64_t jobId_ = 0;
  uint64_t imagesShown_ = 0;
  std::string pendingScreenshot_;
  double lastInput_ = 0.0;
  double fpsWindowStart_ = 0.0;
  int fpsFrames_ = 0;
  float fps_ = 0.0f;
};

// Runs the viewer as the options say (window or headless, frames, screenshot, benchmark).
int runViewer(const ViewerOptions& options);
// Frames per second and time to first image, headless, for the given integrators.
int runViewerBenchmark(const ViewerOptions& options);

}  // namespace pathway
