#include "io/exr_files.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <algorithm>
#include <cstdint>
#include <exception>
#include <filesystem>

#include "core/error.h"

namespace pathway {
namespace {

// A frame buffer over channel-interleaved floats: channel c of pixel (x, y) is at
// pixels[(y * width + x) * count + c].
Imf::FrameBuffer interleavedFrameBuffer(const std::vector<std::string>& channels, int width,
                                        const float* pixels) {
  Imf::FrameBuffer frame;
  const size_t count = channels.size();
  for (size_t c = 0; c < count; ++c)
    frame.insert(channels[c], Imf::Slice(Imf::FLOAT, (char*)(pixels + c), sizeof(float) * count,
                                         sizeof(float) * count * width));
  return frame;
}

}  // namespace

void writeExrRaster(const std::string& path, const RasterHeader& header, const float* pixels) {
  try {
    Imf::Header exr(header.width, header.height);
    exr.compression() = header.compressed ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
    for (const std::string& name : header.channels)
      exr.channels().insert(name, Imf::Channel(Imf::FLOAT));
    for (const auto& [key, value] : header.attributes) exr.insert(key, Imf::StringAttribute(value));
    Imf::OutputFile file(path.c_str(), exr);
    file.setFrameBuffer(interleavedFrameBuffer(header.channels, header.width, pixels));
    file.writePixels(header.height);
  } catch (const std::exception& error) {
    throw PathwayError(path + ": writing failed: " + error.what());
  }
}

Raster readExrRaster(const std::string& path, const RasterLimits& limits) {
  try {
    if (limits.width > 0 && limits.height > 0 && limits.maxChannels > 0) {
      // Uncompressed float pixels, the header and the offset table: a file past that is no
      // image of this size (and not read at all).
      const uint64_t most = uint64_t(limits.width) * limits.height * limits.maxChannels * 4 +
                            uint64_t(limits.height) * 16 + (1u << 20);
      std::error_code error;
      const uintmax_t size = std::filesystem::file_size(path, error);
      if (!error && size > most)
        throw PathwayError(path + ": cannot read image: " + std::to_string(size) +
                           " bytes, more than a " + std::to_string(limits.width) + "x" +
                           std::to_string(limits.height) + " image can take");
    }
    Imf::InputFile file(path.c_str());
    const Imf::Header& exr = file.header();
    const Imath::Box2i window = exr.dataWindow();
    Raster raster;
    RasterHeader& header = raster.header;
    header.width = window.max.x - window.min.x + 1;
    header.height = window.max.y - window.min.y + 1;
    if (header.width <= 0 || header.height <= 0)
      throw PathwayError(path + ": cannot read image: empty data window");
    if ((limits.width > 0 && header.width != limits.width) ||
        (limits.height > 0 && header.height != limits.height))
      throw PathwayError(path + ": cannot read image: it declares " + std::to_string(header.width) +
                         "x" + std::to_string(header.height) + " pixels, not the " +
                         std::to_string(limits.width) + "x" + std::to_string(limits.height) +
                         " expected");
    std::vector<std::string> others;
    // Unsigned channels are a part's film sums (io/partial_film.h), not pixel values.
    for (auto channel = exr.channels().begin(); channel != exr.channels().end(); ++channel)
      if (channel.channel().type != Imf::UINT) others.push_back(channel.name());
    for (const char* name : {"R", "G", "B"}) {
      const auto found = std::find(others.begin(), others.end(), name);
      if (found == others.end()) continue;
      header.channels.push_back(name);
      others.erase(found);
    }
    header.channels.insert(header.channels.end(), others.begin(), others.end());
    if (limits.maxChannels > 0 && header.channels.size() > limits.maxChannels)
      throw PathwayError(path + ": cannot read image: " + std::to_string(header.channels.size()) +
                         " channels, more than the " + std::to_string(limits.maxChannels) +
                         " expected");
    for (auto attribute = exr.begin(); attribute != exr.end(); ++attribute)
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&attribute.attribute()))
        header.attributes.emplace_back(attribute.name(), text->value());

    raster.pixels.resize(size_t(header.width) * header.height * header.channels.size());
    // The frame buffer is addressed in data-window coordinates: shift its base to the window's
    // first pixel.
    const size_t count = header.channels.size();
    const ptrdiff_t origin = (ptrdiff_t(window.min.y) * header.width + window.min.x) * count;
    file.setFrameBuffer(
        interleavedFrameBuffer(header.channels, header.width, raster.pixels.data() - origin));
    file.readPixels(window.min.y, window.max.y);
    return raster;
  } catch (const PathwayError&) {
    throw;
  } catch (const std::exception& error) {
    throw PathwayError(path + ": cannot read image: " + error.what());
  }
}

}  // namespace pathway
