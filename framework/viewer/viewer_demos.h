// The lecture's live demos, by name: `pathway view --demo nested-vs-4d` starts the viewer with the
// scene, integrators, split view, balance and display a demo needs, so a lecturer never types
// settings in class. Each demo is declared once here; `pathway view --list-demos`, the slides and
// the tests read this table.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "viewer/viewer_options.h"

namespace pathway {

struct ViewerDemo {
  std::string name;
  std::string shows;  // one line: what the demo is there to show
  std::string keys;   // one line: the keys that drive it in class
  std::string scene;  // relative to the scenes folder
  std::string integrator;
  std::vector<std::string> params;  // name=value
  std::string splitIntegrator;      // empty: one pane
  std::vector<std::string> splitParams;
  std::string balance = "time";  // split view: time or rays
  std::string sampler;           // empty: the left integrator's own
  std::string splitSampler;      // the right pane's own; empty: the left pane's
  std::string splitFilter;       // the right pane's own; empty: the left pane's
  std::string display = "color";
  float scaleTop = kScaleTop.defaultAs<float>();  // a fixed top for the false-colour display
  float lightScale = setting::kLightScale.defaultAs<float>();  // the lights' size at the start
  bool makeReference = false;  // make the error plot's reference once the first image is in
  std::string filter;          // empty: the default (box)
  uint32_t spp = 0;            // the spp target; 0: the viewer's default
  // Render width of a pane (the height follows the camera): fixed, so the reference made once by
  // --prepare-demos fits whatever window the lecture runs in, and small enough that the first
  // image comes within a second or two on 2 cores.
  int width = 400;
};

const std::vector<ViewerDemo>& viewerDemos();

// Sets everything the demo decides in `options`: scene, integrators and parameters, split view,
// balance, samplers, display, filter, spp target, render width (unless --width or --height is
// given) and the error-plot reference, kept in and found in the reference cache
// (reference_cache.h). The rest (window, headless, screenshot, reference spp) stays as given.
// Throws PathwayError naming the known demos for an unknown name.
void applyViewerDemo(const std::string& name, ViewerOptions& options);

// The options the demo stands for, as they would be typed after `pathway view`.
std::string describeViewerDemo(const ViewerDemo& demo);

}  // namespace pathway
