#include "io/partial_film.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cstring>
#include <exception>
#include <vector>

#include "core/error.h"
#include "io/raster_files.h"

namespace pathway {
namespace {

// The film's double sums, in the order they are stored.
struct SumField {
  const char* name;
  double& (*of)(PixelSums&);
};
const SumField kSumFields[] = {
    {"wL.R", [](PixelSums& p) -> double& { return p.weightedRadiance.x; }},
    {"wL.G", [](PixelSums& p) -> double& { return p.weightedRadiance.y; }},
    {"wL.B", [](PixelSums& p) -> double& { return p.weightedRadiance.z; }},
    {"w", [](PixelSums& p) -> double& { return p.weight; }},
    {"absW", [](PixelSums& p) -> double& { return p.absWeight; }},
    {"w2L.R", [](PixelSums& p) -> double& { return p.squaredWeightRadiance.x; }},
    {"w2L.G", [](PixelSums& p) -> double& { return p.squaredWeightRadiance.y; }},
    {"w2L.B", [](PixelSums& p) -> double& { return p.squaredWeightRadiance.z; }},
    {"w2L2.R", [](PixelSums& p) -> double& { return p.squaredWeightRadiance2.x; }},
    {"w2L2.G", [](PixelSums& p) -> double& { return p.squaredWeightRadiance2.y; }},
    {"w2L2.B", [](PixelSums& p) -> double& { return p.squaredWeightRadiance2.z; }},
    {"w2", [](PixelSums& p) -> double& { return p.squaredWeight; }},
};
constexpr size_t kSumCount = sizeof kSumFields / sizeof kSumFields[0];
// Two words per double, then the sample count.
constexpr size_t kWordsPerPixel = 2 * kSumCount + 1;
const char* const kImageChannels[] = {"R",          "G",          "B",     "variance.R",
                                      "variance.G", "variance.B", "weight"};
constexpr size_t kImageChannelCount = sizeof kImageChannels / sizeof kImageChannels[0];

std::vector<std::string> wordChannels() {
  std::vector<std::string> names;
  for (const SumField& field : kSumFields) {
    names.push_back(std::string("film.") + field.name + ".hi");
    names.push_back(std::string("film.") + field.name + ".lo");
  }
  names.push_back("film.count");
  return names;
}

// Slices of an interleaved buffer of `count` values of `type` per pixel, starting at `base`.
void insertSlices(Imf::FrameBuffer& frame, const std::vector<std::string>& names,
                  Imf::PixelType type, char* base, size_t valueSize, int width) {
  const size_t stride = valueSize * names.size();
  for (size_t c = 0; c < names.size(); ++c)
    frame.insert(names[c], Imf::Slice(type, base + c * valueSize, stride, stride * width));
}

}  // namespace

void writePartialFilm(const std::string& path, const Film& film, const FilmImages& images,
                      const RenderMetadata& metadata) {
  checkImagePath(path);
  if (lowerExtension(path) != ".exr")
    throw PathwayError(path + ": a part of a render is written as .exr only");
  const int width = film.width(), height = film.height();
  const size_t pixels = static_cast<size_t>(width) * height;
  std::vector<float> image(pixels * kImageChannelCount);
  std::vector<uint32_t> words(pixels * kWordsPerPixel);
  for (size_t i = 0; i < pixels; ++i) {
    float* value = &image[i * kImageChannelCount];
    for (int c = 0; c < 3; ++c) {
      value[c] = images.color.pixels[i][c];
      value[3 + c] = images.variance.pixels[i][c];
    }
    value[6] = images.weight.pixels[i].x;
    PixelSums sums = film.at(static_cast<int>(i % width), static_cast<int>(i / width));
    uint32_t* word = &words[i * kWordsPerPixel];
    for (const SumField& field : kSumFields) {
      uint64_t bits;
      std::memcpy(&bits, &field.of(sums), sizeof bits);
      *word++ = static_cast<uint32_t>(bits >> 32);
      *word++ = static_cast<uint32_t>(bits);
    }
    *word = sums.sampleCount;
  }
  writeThroughTemporary(path, [&](const std::string& temporary) {
    try {
      Imf::Header exr(width, height);
      // ZIP, unlike a rendered image (io/exr_files.cpp): the sums' high words compress well, so a
      // part takes half the bytes on the cluster's shared disk, for a write that a task's render
      // time dwarfs.
      exr.compression() = Imf::ZIP_COMPRESSION;
      const std::vector<std::string> imageNames(kImageChannels,
                                                kImageChannels + kImageChannelCount);
      const std::vector<std::string> wordNames = wordChannels();
      for (const std::string& name : imageNames) exr.channels().insert(name, Imf::FLOAT);
      for (const std::string& name : wordNames) exr.channels().insert(name, Imf::UINT);
      for (const auto& [key, value] : metadataAttributes(metadata))
        exr.insert(key, Imf::StringAttribute(value));
      Imf::FrameBuffer frame;
      insertSlices(frame, imageNames, Imf::FLOAT, reinterpret_cast<char*>(image.data()),
                   sizeof(float), width);
      insertSlices(frame, wordNames, Imf::UINT, reinterpret_cast<char*>(words.data()),
                   sizeof(uint32_t), width);
      Imf::OutputFile file(temporary.c_str(), exr);
      file.setFrameBuffer(frame);
      file.writePixels(height);
    } catch (const std::exception& error) {
      throw PathwayError(temporary + ": writing failed: " + error.what());
    }
  });
}

PartialFilm readPartialFilm(const std::string& path, bool withSums) {
  PartialFilm part;
  try {
    Imf::InputFile file(path.c_str());
    const Imf::Header& exr = file.header();
    std::vector<std::pair<std::string, std::string>> attributes;
    for (auto attribute = exr.begin(); attribute != exr.end(); ++attribute)
      if (const auto* text = dynamic_cast<const Imf::StringAttribute*>(&attribute.attribute()))
        attributes.emplace_back(attribute.name(), text->value());
    part.metadata = readMetadataAttributes(attributes, path);
    const std::vector<std::string> wordNames = wordChannels();
    for (const std::string& name : wordNames) {
      const Imf::Channel* channel = exr.channels().findChannel(name);
      if (!channel || channel->type != Imf::UINT)
        throw PathwayError(path +
                           ": not a part of a render (no film sums: render it with --samples A:B "
                           "to an .exr)");
    }
    if (part.metadata.samplesOfWhole == 0)
      throw PathwayError(path + ": its sample range is missing");

    const Imath::Box2i window = exr.dataWindow();
    const int width = part.width = window.max.x - window.min.x + 1;
    const int height = part.height = window.max.y - window.min.y + 1;
    if (!withSums) return part;
    std::vector<uint32_t> words(static_cast<size_t>(width) * height * kWordsPerPixel);
    Imf::FrameBuffer frame;
    // Addressed in data-window coordinates: shift the base to the window's first pixel.
    const ptrdiff_t origin =
        (ptrdiff_t(window.min.y) * width + window.min.x) * ptrdiff_t(kWordsPerPixel);
    insertSlices(frame, wordNames, Imf::UINT, reinterpret_cast<char*>(words.data() - origin),
                 sizeof(uint32_t), width);
    file.setFrameBuffer(frame);
    file.readPixels(window.min.y, window.max.y);

    part.film = Film(width, height);
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        PixelSums& sums = part.film.at(x, y);
        const uint32_t* word = &words[(static_cast<size_t>(y) * width + x) * kWordsPerPixel];
        for (const SumField& field : kSumFields) {
          const uint64_t bits = (uint64_t(word[0]) << 32) | word[1];
          std::memcpy(&field.of(sums), &bits, sizeof bits);
          word += 2;
        }
        sums.sampleCount = *word;
      }
  } catch (const PathwayError&) {
    throw;
  } catch (const std::exception& error) {
    throw PathwayError(path + ": cannot read the part: " + error.what());
  }
  return part;
}

}  // namespace pathway
