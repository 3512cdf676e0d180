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

  ViewerDemo* demo = &add("nested-vs-4d",
                          "AO as two nested integrals (4 AO rays per eye ray) beside one 4D "
                          "integral, at equal rays, with their error plots",
                          "cornell_box.gltf", "stage2@ref", {"ao-rays=4"});
  demo->splitIntegrator = "stage3@ref";
  demo->balance = "rays";
  demo->sampler = "sobol";
  demo->makeReference = true;

  // Path tracing on the left: the error plot's reference is made by the left pane.
  demo = &add("naive-vs-path",
              "path tracing beside naive recursion (3 rays per hit), both 3 bounces deep, at "
              "equal time",
              "cornell_box.gltf", "stage5@ref", {"max-depth=3"});
  demo->splitIntegrator = "stage4@ref";
  demo->splitParams = {"branching=3", "depth=3"};
  demo->makeReference = true;

  // The error plot's reference is made by the left pane: the one with NEE, far less noisy.
  demo = &add("nee-small-light",
              "path tracing with and without next-event estimation under a small light, at "
              "equal rays",
              "small_light.gltf", "stage5@ref", {"nee=on"});
  demo->splitIntegrator = "stage5@ref";
  demo->splitParams = {"nee=off"};
  demo->balance = "rays";
  demo->makeReference = true;

  demo = &add("ray-explosion",
              "rays per camera sample of naive recursion (4 rays per hit, depth 3) as a heatmap",
              "cornell_box.gltf", "stage4@ref", {"branching=4", "depth=3"});
  demo->display = "rays";

  demo = &add("mitchell-lobes",
              "the Mitchell-Netravali filter at 2 samples per pixel: sharp edges, negative "
              "lobes, and numerical normalisation keeping flat regions flat",
              "grading_edges.gltf", "stage1@ref", {});
  demo->filter = "mitchell";
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
    options.balance = demo.balance;
    options.display = demo.display;
    options.makeReference = options.makeReference || demo.makeReference;
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
    line += " --balance " + demo.balance;
  }
  if (demo.display != "color") line += " --display " + demo.display;
  if (!demo.filter.empty()) line += " --filter " + demo.filter;
  if (demo.spp > 0) line += " --spp " + std::to_string(demo.spp);
  if (demo.makeReference) line += " --make-reference";
  return line;
}

}  // namespace pathway
