// EXR files written and read back: every channel must come back where it was, whatever order the
// file stores channels in (EXR sorts them by name: B, G, R, variance.B, ... weight).
#include "io/image_io.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace pathway {
namespace {

namespace fs = std::filesystem;

Image pattern(int width, int height, float offset) {
  Image image(width, height);
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = Color(offset + i, offset + i + 0.25f, offset + i + 0.5f);
  return image;
}

TEST(ImageFiles, ExrKeepsColourVarianceWeightLayersAndMetadata) {
  const fs::path folder = fs::temp_directory_path() / "pathway_image_io_test";
  fs::create_directories(folder);
  const int width = 5, height = 3;
  FilmImages written{pattern(width, height, 0.0f), pattern(width, height, 1000.0f),
                     pattern(width, height, 2000.0f)};
  for (Color& w : written.weight.pixels) w = Color(w.x);  // one weight channel
  const std::string path = (folder / "film.exr").string();
  writeExr(path, written, {{"pathway:spp", "16"}});
  const LoadedImage read = readImageFile(path);
  EXPECT_EQ(read.images.color.pixels, written.color.pixels);
  EXPECT_EQ(read.images.variance.pixels, written.variance.pixels);
  EXPECT_EQ(read.images.weight.pixels, written.weight.pixels);
  EXPECT_EQ(read.metadata.at("pathway:spp"), "16");

  const Image reference = pattern(width, height, 3000.0f), error = pattern(width, height, 4000.0f);
  const std::string layered = (folder / "layers.exr").string();
  writeExrLayers(layered, {{"", &written.color}, {"reference", &reference}, {"error", &error}}, {});
  const LoadedImage layers = readImageFile(layered);
  EXPECT_EQ(layers.images.color.pixels, written.color.pixels);
  EXPECT_EQ(layers.layers.at("reference").pixels, reference.pixels);
  EXPECT_EQ(layers.layers.at("error").pixels, error.pixels);
  fs::remove_all(folder);
}

}  // namespace
}  // namespace pathway
