#include "viewer/viewer_demos.h"

#include <utility>

#include "core/error.h"

namespace pathway {

namespace {

// One demo per block: what it shows, then only the settings it changes.
std::vector<ViewerDemo> declareDemos() {
  std::vector<ViewerDemo> demos;
  auto add = [&demos](const char* name, const char* shows, const char* scene,
                      const char* integrator, std::vector<std::string> params) -> ViewerDemo& {
    ViewerDemo& demo = demos.emplace_back();
    demo.name = name;
    demo.shows = shows;
    demo.scene = scene;
    demo.integrator = integrator;
    demo.params = std::move(params);
    return demo;
  };

  // Assignment 1's nested AO (independent numbers, a fixed 1:4 split of eye and AO rays) against
  // one 4D integral over well-spread 4D points: with Sobol' on both sides they would look alike.
  ViewerDemo* demo = &add("nested-vs-4d",
                          "AO as two nested integrals (independent numbers, 4 AO rays per eye "
                          "ray) beside one 4D integral (Sobol' 4D points), at equal rays, with "
                          "their error plots",
                          "cornell_box.gltf", "stage2@ref", {"ao-rays=4"});
  demo->keys =
      "left pane's ao-rays slider: the eye:AO split, a knob 4D does not have; B equal rays / "
      "equal time; M make the reference again; D variance";
  demo->splitIntegrator = "stage3@ref";
  demo->balance = "rays";
  demo->sampler = "independent";
  demo->splitSampler = "sobol";
  demo->makeReference = true;

  // Next-event estimation is a step of its own (nee-small-light): off here, so the two panes
  // differ in the recursion alone. Path tracing on the left: it makes the error plot's reference.
  demo = &add("naive-vs-path",
              "path tracing (no next-event estimation) beside naive recursion (3 rays per hit), "
              "both 3 bounces deep, at equal time",
              "cornell_box.gltf", "stage5@ref", {"max-depth=3", "nee=off"});
  demo->keys = "D rays per sample (the explosion); B equal time / equal rays; M reference again";
  demo->splitIntegrator = "stage4@ref";
  demo->splitParams = {"branching=3", "depth=3"};
  demo->makeReference = true;

  // The Cornell box's light, in view, at half its side and the same power: [ and ] halve and
  // double it, and the pane without NEE falls apart as it shrinks while the other barely
  // changes. The error plot's reference is made by the left pane: the one with NEE.
  demo = &add("nee-small-light",
              "path tracing with and without next-event estimation as the light shrinks at "
              "fixed power, at equal rays",
              "cornell_box.gltf", "stage5@ref", {"nee=on"});
  demo->keys =
      "[ / ] light half / twice as large (same power); D variance, one colour scale for both "
      "panes; B equal rays / equal time";
  demo->splitIntegrator = "stage5@ref";
  demo->splitParams = {"nee=off"};
  demo->balance = "rays";
  demo->lightScale = 0.5f;
  demo->makeReference = true;

  // A fixed log scale up to naive recursion's count at depth 5 ((4^6 - 1) / 3 rays): every step
  // of Up moves the left pane's colour one step up it, while path tracing's barely moves.
  demo = &add("ray-explosion",
              "rays per camera sample of naive recursion (4 rays per hit) beside path tracing, "
              "on one log scale, as the depth steps up",
              "cornell_box.gltf", "stage4@ref", {"branching=4", "depth=1"});
  demo->keys = "Up / Down depth of both panes; D colour / variance / rays per sample";
  demo->splitIntegrator = "stage5@ref";
  demo->splitParams = {"max-depth=1"};
  demo->display = "rays";
  demo->scaleTop = 1365.0f;

  // The box filter beside it, with the same seed and spp: what the lobes buy.
  demo = &add("mitchell-lobes",
              "the Mitchell-Netravali filter at 2 samples per pixel beside the box filter with the "
              "same seed: sharper edges, negative lobes, and numerical normalisation keeping "
              "flat regions flat",
              "grading_edges.gltf", "stage1@ref", {});
  demo->keys = "+ / - exposure, to see the lobes; left drag: the edges at other angles; R reset";
  demo->filter = "mitchell";
  demo->splitIntegrator = "stage1@ref";
  demo->splitFilter = "box";
  demo->balance = "rays";
  demo->spp = 2;
  return demos;
}

}  // namespace

const std::vector<ViewerDemo>& viewerDemos() {
  static const std::vector<ViewerDemo> demos = declareDemos();
  return demos;
}

void applyViewerDemo(const std::string& name, ViewerOptions& options) {
  for (const ViewerDemo& demo : viewerDemos()) {
    if (demo.name != name) continue;
    options.choices.scene = std::string(PATHWAY_SOURCE_DIR) + "/scenes/" + demo.scene;
    options.choices.integrator = demo.integrator;
    options.choices.params = demo.params;
    options.choices.sampler = demo.sampler;
    options.splitIntegrator = demo.splitIntegrator;
    options.splitParams = demo.splitParams;
    options.splitSampler = demo.splitSampler;
    options.splitFilter = demo.splitFilter;
    options.balance = demo.balance;
    options.display = demo.display;
    options.scaleTop = demo.scaleTop;
    options.choices.lightScale = demo.lightScale;
    options.makeReference = options.makeReference || demo.makeReference;
    options.cacheReferences = true;
    if (options.width == 0 && options.height == 0) options.width = demo.width;
    options.choices.filter =
        demo.filter.empty() ? setting::kFilter.format(setting::kFilter.defaultValue) : demo.filter;
    options.spp = demo.spp > 0 ? demo.spp : kViewerSamplesPerPixel.defaultAs<uint32_t>();
    return;
  }
  std::string known;
  for (const ViewerDemo& demo : viewerDemos()) known += (known.empty() ? "" : ", ") + demo.name;
  throw PathwayError("unknown demo '" + name + "' (known: " + known + ")");
}

std::string describeViewerDemo(const ViewerDemo& demo) {
  std::string line = "scenes/" + demo.scene + " -i " + demo.integrator;
  for (const std::string& param : demo.params) line += " -p " + param;
  if (!demo.sampler.empty()) line += " --sampler " + demo.sampler;
  if (!demo.splitIntegrator.empty()) {
    line += " --split " + demo.splitIntegrator;
    for (const std::string& param : demo.splitParams) line += " --split-param " + param;
    if (!demo.splitSampler.empty()) line += " --split-sampler " + demo.splitSampler;
    if (!demo.splitFilter.empty()) line += " --split-filter " + demo.splitFilter;
    line += " --balance " + demo.balance;
  }
  if (demo.display != "color") line += " --display " + demo.display;
  if (demo.scaleTop != kScaleTop.defaultValue)
    line += " --scale-top " + kScaleTop.format(demo.scaleTop);
  if (demo.lightScale != setting::kLightScale.defaultValue)
    line += " --light-scale " + setting::kLightScale.format(demo.lightScale);
  if (!demo.filter.empty()) line += " --filter " + demo.filter;
  if (demo.spp > 0) line += " --spp " + std::to_string(demo.spp);
  line += " --width " + std::to_string(demo.width);
  if (demo.makeReference) line += " --make-reference";
  return line;
}

}  // namespace pathway
