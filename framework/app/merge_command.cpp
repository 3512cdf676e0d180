// `pathway merge part*.exr -o out.exr`: the parts of one render (render --samples A:B) into the
// image one render over their union gives (cluster/part_merge.h).
#include <cstdio>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/shared_options.h"
#include "cluster/part_merge.h"
#include "io/partial_film.h"
#include "io/raster_files.h"

namespace pathway {
namespace {

struct MergeOptions {
  std::vector<std::string> parts;
  std::vector<std::string> outputs;
  bool allowIncomplete = false;
  float exposure = setting::kExposure.defaultAs<float>();
  bool quiet = false;
};

int run(const MergeOptions& options) {
  for (const std::string& output : options.outputs) checkImagePath(output);
  const MergedRender merged = mergeParts(options.parts, options.allowIncomplete);
  for (const std::string& output : options.outputs) {
    // The merged EXR is a part too (of the union's range), so merges can be merged again.
    if (lowerExtension(output) == ".exr")
      writePartialFilm(output, merged.film, merged.images, merged.metadata);
    else
      writeImageFile(output, merged.images, merged.metadata, options.exposure);
  }
  if (!options.quiet) {
    std::printf("merged %zu parts: samples %u:%u of %u, %dx%d\n", options.parts.size(),
                merged.metadata.sampleBegin, merged.metadata.sampleEnd,
                merged.metadata.samplesOfWhole, merged.film.width(), merged.film.height());
    for (const std::string& output : options.outputs) std::printf("wrote %s\n", output.c_str());
  }
  return 0;
}

}  // namespace

Command addMergeCommand(CLI::App& app) {
  auto options = std::make_shared<MergeOptions>();
  CLI::App* merge = app.add_subcommand(
      "merge", "Merge the parts of one render (render --samples A:B) into its image");
  merge->footer(
      "Example:\n"
      "  pathway render scene.gltf --spp 64 --samples 0:32 -o a.exr\n"
      "  pathway render scene.gltf --spp 64 --samples 32:64 -o b.exr\n"
      "  pathway merge a.exr b.exr -o whole.exr     (the image of --spp 64 in one render)");
  merge->add_option("parts", options->parts, "The parts (.exr written by render --samples)")
      ->required();
  merge->add_option("-o,--output", options->outputs, "Output file(s): .exr (itself a part) or .png")
      ->required();
  merge->add_flag("--allow-incomplete", options->allowIncomplete,
                  "Accept parts that cover only some of the render's samples (no gaps between "
                  "them)");
  addOption(*merge, setting::kExposure, options->exposure);
  merge->add_flag("-q,--quiet", options->quiet, "No summary");
  return {merge, [options] { return run(*options); }};
}

}  // namespace pathway
