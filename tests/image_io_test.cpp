// EXR files written and read back: every channel must come back where it was, whatever order the
// file stores channels in (EXR sorts them by name: B, G, R, variance.B, ... weight). PNG files
// (written through libpng, read through the image-file module) hold the sRGB encoding of the
// exposed colour, rounded to 8 bits.
#include "io/image_io.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "core/error.h"
#include "io/png_files.h"

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
  FilmImages written{pattern(width, height, 0.0f),
                     pattern(width, height, 1000.0f),
                     pattern(width, height, 2000.0f),
                     {pattern(width, height, 5000.0f), pattern(width, height, 6000.0f)}};
  for (Color& w : written.weight.pixels) w = Color(w.x);  // one weight channel
  const std::string path = (folder / "film.exr").string();
  RenderMetadata metadata;
  metadata.spp = 16;
  writeExr(path, written, metadata);
  const LoadedImage read = readImageFile(path);
  EXPECT_EQ(read.images.color.pixels, written.color.pixels);
  EXPECT_EQ(read.images.variance.pixels, written.variance.pixels);
  EXPECT_EQ(read.images.weight.pixels, written.weight.pixels);
  ASSERT_EQ(read.images.jackknife.size(), 2u);  // the jackknife images, in order, not as layers
  EXPECT_EQ(read.images.jackknife[0].pixels, written.jackknife[0].pixels);
  EXPECT_EQ(read.images.jackknife[1].pixels, written.jackknife[1].pixels);
  EXPECT_TRUE(read.layers.empty());
  EXPECT_EQ(read.metadata.spp, 16u);

  const Image reference = pattern(width, height, 3000.0f), error = pattern(width, height, 4000.0f);
  const std::string layered = (folder / "layers.exr").string();
  writeExrLayers(layered, {{"", &written.color}, {"reference", &reference}, {"error", &error}}, {});
  const LoadedImage layers = readImageFile(layered);
  EXPECT_EQ(layers.images.color.pixels, written.color.pixels);
  EXPECT_EQ(layers.layers.at("reference").pixels, reference.pixels);
  EXPECT_EQ(layers.layers.at("error").pixels, error.pixels);
  fs::remove_all(folder);
}

// Renders are written uncompressed (noise barely compresses, and ZIP took a fifth of a short
// render's time); references, written as layers, are ZIP-compressed (converged images shrink to a
// quarter). A flat image shows which is which by its size.
TEST(ImageFiles, RendersAreWrittenUncompressedAndLayeredReferencesCompressed) {
  const fs::path folder = fs::temp_directory_path() / "pathway_image_io_compression_test";
  fs::create_directories(folder);
  const int width = 64, height = 64;
  const size_t floats = size_t(width) * height;  // bytes of one float channel / 4
  Image flat(width, height);
  for (Color& pixel : flat.pixels) pixel = Color(0.5f);
  const std::string render = (folder / "render.exr").string();
  writeExr(render, FilmImages{flat, flat, flat, {}}, {});
  EXPECT_GE(fs::file_size(render), 7 * 4 * floats);  // R, G, B, three variances, weight
  const std::string reference = (folder / "reference.exr").string();
  writeExrLayers(reference, {{"", &flat}, {"variance", &flat}}, {});
  EXPECT_LT(fs::file_size(reference), 6 * 4 * floats / 10);
  fs::remove_all(folder);
}

// The sRGB transfer function as IEC 61966-2-1 defines it, clipped to [0, 1], as an 8-bit value.
float srgbByte(double linear) {
  const double v = std::fmin(1.0, std::fmax(0.0, linear));
  const double encoded = v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1.0 / 2.4) - 0.055;
  return static_cast<float>(std::lround(255.0 * encoded));
}

TEST(ImageFiles, PngHoldsTheSrgbEncodingOfTheExposedColour) {
  const fs::path folder = fs::temp_directory_path() / "pathway_image_io_png_test";
  fs::create_directories(folder);
  const float values[] = {-1.0f, 0.0f, 0.002f, 0.05f, 0.18f, 0.25f, 0.5f, 1.0f, 3.0f};
  const int width = 3, height = 3;  // one value per pixel, in R; G and B hold other values
  Image image(width, height);
  for (int i = 0; i < width * height; ++i)
    image.pixels[i] = Color(values[i], values[(i + 3) % 9], values[(i + 6) % 9]);
  for (const float exposure : {0.0f, 1.0f}) {
    const std::string path = (folder / "colour.png").string();
    writePng(path, image, exposure);
    const LoadedImage read = readImageFile(path);
    ASSERT_EQ(read.images.color.width, width);
    ASSERT_EQ(read.images.color.height, height);
    for (int i = 0; i < width * height; ++i)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(std::lround(255.0f * read.images.color.pixels[i][c]),
                  srgbByte(std::exp2(exposure) * image.pixels[i][c]))
            << "pixel " << i << ", channel " << c << ", exposure " << exposure;
  }
  EXPECT_FALSE(fs::exists(folder / ".partial-colour.png"));

  const uint8_t pixels[5] = {};
  const std::string tooMany = (folder / "five.png").string();
  try {
    writePngRaster(tooMany, {1, 1, {"R", "G", "B", "A", "Z"}, {}}, pixels);
    ADD_FAILURE() << "five channels were accepted";
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find(tooMany), std::string::npos) << error.what();
  }
  EXPECT_FALSE(fs::exists(tooMany));
  fs::remove_all(folder);
}

}  // namespace
}  // namespace pathway
