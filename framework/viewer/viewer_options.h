// What `pathway view` is asked for on its command line (or by a lecture demo, viewer_demos.h),
// before it is checked into a ViewerState. GL-free, so the tests and the demos can use it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "engine/render_choices.h"

namespace pathway {

// The viewer refines a pane until it reaches this many samples per pixel: the render setting's
// spp, with a far larger default (same range).
inline const OptionSpec kViewerSamplesPerPixel =
    setting::kSamplesPerPixel.withDefault(4096, "Samples per pixel at which rendering stops");

// A fixed top for the false-colour displays, so that a count stepping up shows as a colour moving
// up (the ray explosion) instead of a scale that follows it.
inline const OptionSpec kScaleTop = OptionSpec::real(
    "scale-top", 0.0, 0.0, 1e30,
    "Top of the variance and rays-per-sample colour scale (0: the images' own, 99th percentile)");

struct ViewerOptions {
  RenderChoices choices;        // scene, integrator, parameters, sampler, seed, filter
  std::string splitIntegrator;  // non-empty: split view with this on the right
  std::vector<std::string> splitParams;
  std::string splitSampler;  // the right pane's own sampler (setting::kSampler); empty: the left's
  std::string splitFilter;   // the right pane's own filter (setting::kFilter); empty: the left's
  std::string balance = "time";  // split view: "time" or "rays"
  int windowWidth = 1280, windowHeight = 720;
  int width = 0, height = 0;  // render size; 0: follow the pane
  uint32_t spp = kViewerSamplesPerPixel.defaultAs<uint32_t>();
  uint32_t samplesPerPass = setting::kSamplesPerPass.defaultAs<uint32_t>();
  float exposure = setting::kExposure.defaultAs<float>();
  std::string display = "color";
  float scaleTop = kScaleTop.defaultAs<float>();
  bool showHelp = false;  // open with the keys-and-mouse overlay
  bool headless = false;
  int frames = 0;          // > 0: draw this many frames, then exit
  std::string screenshot;  // written after the last frame
  bool grade = false;      // headless: grade the left pane once its first image is in (key G)
  std::string reference;   // an EXR the error plot measures the panes against
  uint32_t referenceSpp = setting::kReferenceSamplesPerPixel.defaultAs<uint32_t>();
  bool makeReference = false;  // headless: make the reference once the first image is in (key M)
  // Keep the references made on disk and use them again (reference_cache.h): the demos do.
  bool cacheReferences = false;
  bool prepareReference = false;  // headless: exit once the reference is made (and cached)
  bool benchmark = false;
  double benchmarkSeconds = 3.0;
};

}  // namespace pathway
