#include "viewer/reference_cache.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <map>
#include <sstream>

#include "core/error.h"
#include "core/number_format.h"
#include "core/stable_hash.h"
#include "io/image_io.h"
#include "viewer/stage_reference.h"

namespace pathway {
namespace {

// One entry: the image, and beside it the key it was made for.
std::filesystem::path entryOf(const std::filesystem::path& folder, const std::string& key) {
  return folder / (hexDigits(stableHash(key)) + ".exr");
}

std::filesystem::path keyFileOf(const std::filesystem::path& image) {
  std::filesystem::path file = image;
  return file.replace_extension(".key");
}

std::string readWhole(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::filesystem::path referenceCacheFolder() {
  if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache && *cache)
    return std::filesystem::path(cache) / "pathway" / "references";
  const char* home = std::getenv("HOME");
  return std::filesystem::path(home && *home ? home : ".") / ".cache" / "pathway" / "references";
}

std::string referenceCacheKey(const LaneFrame& frame, const LoadedScene& scene, uint32_t spp) {
  const IntegratorInfo* reference = stageReferenceOf(frame.integrator);
  const RenderSettings& s = frame.settings;
  const CameraPose& c = frame.camera;
  std::ostringstream key;
  key.precision(9);  // every float exactly
  key << (reference ? reference->name : frame.integrator) << " " << frame.params.describe()
      << " scene=" << hexDigits(scene.contentHash) << " camera=" << c.position.x << ","
      << c.position.y << "," << c.position.z << "/" << c.lookAt.x << "," << c.lookAt.y << ","
      << c.lookAt.z << "/" << c.up.x << "," << c.up.y << "," << c.up.z << "/" << c.yfov
      << " size=" << s.width << "x" << s.height << " filter=" << filterTypeName(s.filter) << ":"
      << s.filterRadiusPixels() << " sampler=" << samplerTypeName(s.sampler)
      << " seed=" << referenceSeed(s.seed) << " spp=" << spp;
  return key.str();
}

std::optional<ReferenceImage> loadCachedReference(const std::filesystem::path& folder,
                                                  const LaneFrame& frame, const LoadedScene& scene,
                                                  uint32_t spp) {
  const std::string key = referenceCacheKey(frame, scene, spp);
  const std::filesystem::path image = entryOf(folder, key);
  std::error_code error;
  if (!std::filesystem::is_regular_file(image, error) || readWhole(keyFileOf(image)) != key)
    return std::nullopt;
  try {
    ReferenceImage reference = loadReference(image.string(), viewOf(frame));
    if (reference.image.width != frame.settings.width ||
        reference.image.height != frame.settings.height)
      return std::nullopt;
    reference.fromFile = false;  // made by this program for this view, as Make reference does
    // What made it, not where it is kept: the panel (and a screenshot of it) shows no folder.
    const IntegratorInfo* made = stageReferenceOf(frame.integrator);
    reference.source =
        (made ? made->name : frame.integrator) + ", " + std::to_string(spp) + " spp, cached";
    reference.seed = referenceSeed(frame.settings.seed);
    reference.sampler = frame.settings.sampler;
    return reference;
  } catch (const std::exception&) {
    return std::nullopt;  // a damaged entry: made again, and written over
  }
}

void storeCachedReference(const std::filesystem::path& folder, const LaneFrame& frame,
                          const LoadedScene& scene, uint32_t spp, const ReferenceImage& reference) {
  const std::string key = referenceCacheKey(frame, scene, spp);
  const std::filesystem::path image = entryOf(folder, key);
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  if (error)
    throw PathwayError(folder.string() + ": cannot make the reference cache (" + error.message() +
                       ")");
  RenderMetadata metadata;
  const IntegratorInfo* made = stageReferenceOf(frame.integrator);
  metadata.integrator = made ? made->name : frame.integrator;
  metadata.spp = spp;
  // The key first: an image without its key is never read.
  writeThroughTemporary(keyFileOf(image).string(), [&](const std::string& path) {
    std::ofstream out(path, std::ios::binary);
    out << key;
    if (!out.flush()) throw PathwayError(path + ": cannot write");
  });
  writeThroughTemporary(image.string(), [&](const std::string& path) {
    writeExrLayers(path, {{"", &reference.image}}, metadata);
  });
}

}  // namespace pathway
