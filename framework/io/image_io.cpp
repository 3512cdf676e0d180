#include "io/image_io.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "core/error.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// Writes `pixels` (channel-interleaved) through OIIO to a temporary file, then renames it.
void writeAtomically(const std::string& path, const OIIO::ImageSpec& spec, OIIO::TypeDesc type,
                     const void* pixels) {
  checkImagePath(path);
  const fs::path target(path);
  const fs::path temporary =
      target.parent_path() / (".partial-" + target.stem().string() + target.extension().string());
  auto out = OIIO::ImageOutput::create(temporary.string());
  if (!out) throw PathwayError(path + ": cannot write this image format: " + OIIO::geterror());
  bool ok = out->open(temporary.string(), spec) && out->write_image(type, pixels) && out->close();
  if (!ok) {
    const std::string reason = out->geterror();
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw PathwayError(path + ": writing failed: " + reason);
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) {
    fs::remove(temporary, error);
    throw PathwayError(path + ": could not move the finished image into place");
  }
}

}  // namespace

void checkImagePath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext != ".exr" && ext != ".png")
    throw PathwayError(path + ": unknown image type '" + ext + "' (use .exr or .png)");
  const fs::path target(path);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path()))
    throw PathwayError(path + ": the folder " + target.parent_path().string() + " does not exist");
}

float linearToSrgb(float linear) {
  const float v = std::clamp(linear, 0.0f, 1.0f);
  return v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
}

void writeExr(const std::string& path, const FilmImages& images, const ImageMetadata& metadata) {
  const Image& color = images.color;
  const bool extras = images.variance.width == color.width && images.weight.width == color.width;
  const int channels = extras ? 7 : 3;
  OIIO::ImageSpec spec(color.width, color.height, channels, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"R", "G", "B"};
  if (extras) {
    for (const char* name : {"variance.R", "variance.G", "variance.B", "weight"})
      spec.channelnames.push_back(name);
  }
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  std::vector<float> data;
  data.reserve(color.pixels.size() * channels);
  for (size_t i = 0; i < color.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) data.push_back(color.pixels[i][c]);
    if (!extras) continue;
    for (int c = 0; c < 3; ++c) data.push_back(images.variance.pixels[i][c]);
    data.push_back(images.weight.pixels[i].x);
  }
  writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, data.data());
}

void writeExrLayers(const std::string& path, const std::map<std::string, const Image*>& layers,
                    const ImageMetadata& metadata) {
  const Image& first = *layers.begin()->second;
  OIIO::ImageSpec spec(first.width, first.height, static_cast<int>(3 * layers.size()),
                       OIIO::TypeDesc::FLOAT);
  spec.channelnames.clear();
  for (const auto& [name, image] : layers) {
    if (image->width != first.width || image->height != first.height)
      throw PathwayError(path + ": internal: layer '" + name + "' has another size");
    for (const char* c : {"R", "G", "B"})
      spec.channelnames.push_back(name.empty() ? std::string(c) : name + "." + c);
  }
  for (const auto& [key, value] : metadata) spec.attribute(key, value);
  std::vector<float> data;
  data.reserve(first.pixels.size() * spec.nchannels);
  for (size_t i = 0; i < first.pixels.size(); ++i)
    for (const auto& entry : layers)
      for (int c = 0; c < 3; ++c) data.push_back(entry.second->pixels[i][c]);
  writeAtomically(path, spec, OIIO::TypeDesc::FLOAT, data.data());
}

void writePng(const std::string& path, const Image& image, float exposure) {
  const float scale = std::exp2(exposure);
  std::vector<unsigned char> data;
  data.reserve(image.pixels.size() * 3);
  for (const Color& pixel : image.pixels)
    for (int c = 0; c < 3; ++c)
      data.push_back(
          static_cast<unsigned char>(std::lround(255.0f * linearToSrgb(scale * pixel[c]))));
  OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
  writeAtomically(path, spec, OIIO::TypeDesc::UINT8, data.data());
}

void writeImageFile(const std::string& path, const FilmImages& images,
                    const ImageMetadata& metadata, float exposure) {
  checkImagePath(path);
  if (lowerExtension(path) == ".exr") return writeExr(path, images, metadata);
  writePng(path, images.color, exposure);
}

LoadedImage readImageFile(const std::string& path) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw PathwayError(path + ": cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  std::vector<float> data(static_cast<size_t>(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, data.data()))
    throw PathwayError(path + ": cannot read image: " + in->geterror());

  LoadedImage loaded;
  auto channel = [&](const std::string& name) {
    for (int c = 0; c < spec.nchannels; ++c)
      if (spec.channelnames[c] == name) return c;
    return -1;
  };
  auto extract = [&](Image& image, int first, int count) {
    image = Image(spec.width, spec.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int c = 0; c < 3; ++c)
        image.pixels[i][c] = data[i * spec.nchannels + first + std::min(c, count - 1)];
  };
  const bool isColor = spec.nchannels >= 3;
  extract(loaded.images.color, 0, isColor ? 3 : 1);
  if (channel("variance.R") >= 0) extract(loaded.images.variance, channel("variance.R"), 3);
  if (channel("weight") >= 0) extract(loaded.images.weight, channel("weight"), 1);
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[c];
    const size_t dot = name.rfind('.');
    if (dot == std::string::npos || name.substr(dot) != ".R") continue;
    const std::string layer = name.substr(0, dot);
    if (layer == "variance" || channel(layer + ".G") < 0 || channel(layer + ".B") < 0) continue;
    const int index[3] = {c, channel(layer + ".G"), channel(layer + ".B")};
    Image& image = loaded.layers[layer];
    image = Image(spec.width, spec.height);
    for (size_t i = 0; i < image.pixels.size(); ++i)
      for (int k = 0; k < 3; ++k) image.pixels[i][k] = data[i * spec.nchannels + index[k]];
  }
  for (const OIIO::ParamValue& param : spec.extra_attribs) {
    const std::string name = param.name().string();
    if (name.rfind("pathway:", 0) == 0) loaded.metadata[name] = param.get_string();
  }
  in->close();
  return loaded;
}

}  // namespace pathway
