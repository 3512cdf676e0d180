#include "viewer/reference_image.h"

#include <cctype>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>

#include "core/error.h"
#include "core/number_format.h"
#include "io/image_io.h"
#include "render/integrator_registry.h"

namespace pathway {
namespace {

std::string sizeText(int width, int height) {
  return std::to_string(width) + " x " + std::to_string(height);
}

std::string radiusText(float radius) {
  return formatNumber("%.2g", radius);
}

}  // namespace

ReferenceView viewOf(const LaneFrame& frame) {
  return {frame.scenePath,
          frame.sceneContent,
          frame.camera,
          frame.settings.filter,
          frame.settings.filterRadiusPixels(),
          frame.params};
}

ReferenceImage loadReference(const std::string& path, const ReferenceView& view) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".exr")
    throw PathwayError(path +
                       ": a reference must be an EXR file (linear radiance, as pathway "
                       "render writes it)");
  if (!std::filesystem::is_regular_file(path))
    throw PathwayError(path + ": no such reference file");
  LoadedImage loaded = readImageFile(path);  // names the file when it cannot read it
  ReferenceImage reference;
  reference.image = std::move(loaded.images.color);
  for (const Color& pixel : reference.image.pixels)
    if (!std::isfinite(pixel.x) || !std::isfinite(pixel.y) || !std::isfinite(pixel.z))
      throw PathwayError(path + ": the reference has non-finite pixel values");
  reference.source = path;
  const RenderMetadata& made = loaded.metadata;
  if (!made.integrator.empty() && made.spp > 0)
    reference.source += " (" + made.integrator + ", " + std::to_string(made.spp) + " spp)";
  reference.fromFile = true;
  reference.view = view;
  // A file from `pathway render` says which filter and random numbers made it.
  if (made.filter) {
    reference.view.filter = *made.filter;
    reference.view.filterRadius = made.filterRadius;
  }
  reference.seed = made.seed;
  reference.sampler = made.sampler;
  if (!made.integrator.empty() && !made.params.empty()) {
    // Parameters of an integrator this program does not have cannot be compared: left out.
    const IntegratorInfo* info = nullptr;
    for (const IntegratorInfo* known : allIntegrators())
      if (known->name == made.integrator) info = known;
    try {
      const std::map<std::string, std::string> given = parseParamList(made.params);
      if (info) reference.view.params = resolveParams(info->name, info->params, given);
    } catch (const std::exception& error) {
      throw PathwayError(path + ": unreadable pathway metadata: " + error.what());
    }
  }
  return reference;
}

std::string referenceProblem(const ReferenceImage& reference, const LaneFrame& frame) {
  const Image& image = frame.images.color;
  const Image& expected = reference.image;
  const bool sameSize = image.width == expected.width && image.height == expected.height;
  if (reference.fromFile && !sameSize)
    return "the reference is " + sizeText(expected.width, expected.height) +
           " pixels but the pane renders " + sizeText(image.width, image.height) +
           ": start the viewer with --width " + std::to_string(expected.width) + " --height " +
           std::to_string(expected.height) + ", or make a reference (M)";
  const ReferenceView view = viewOf(frame);
  const ReferenceView& made = reference.view;
  std::string why;
  if (view.scenePath != made.scenePath)
    why = "another scene is open";
  else if (view.sceneContent != made.sceneContent)
    why = "the scene changed (the light size, or the file opened again)";
  else if (view.camera != made.camera)
    why = "the camera moved";
  else if (!sameSize)
    why = "the render size changed";
  else if (view.filter != made.filter ||  // the metadata's radius has six decimals
           std::fabs(view.filterRadius - made.filterRadius) > 1e-4f)
    why = "the reference has another pixel filter (" + filterTypeName(made.filter) + ", " +
          radiusText(made.filterRadius) + " px)";
  else if (const std::string difference = expectedImageDifference(frame.params, made.params);
           !difference.empty())
    why = "the pane renders with " + difference + ", which changes the expected image";
  if (why.empty()) {
    const bool sameSampler = !reference.sampler || *reference.sampler == frame.settings.sampler;
    if (reference.seed && *reference.seed == frame.settings.seed && sameSampler)
      return "the reference has the pane's seed (" + std::to_string(frame.settings.seed) +
             "): the pane would repeat its samples. Render it with another --seed, or change "
             "the seed under Sampling";
    return "";
  }
  return "reference stale: " + why +
         (reference.fromFile ? " (R resets the camera; M makes a new reference)"
                             : " (M makes a new one)");
}

}  // namespace pathway
