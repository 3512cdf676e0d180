#include "viewer/gl_display.h"

#include <cstring>

#include "core/error.h"
#include "io/raster_files.h"

namespace pathway {

GlTexture::GlTexture(const GlFunctions& gl) : gl_(gl) {
  gl_.GenTextures(1, &id_);
  gl_.BindTexture(GL_TEXTURE_2D, id_);
  // Magnified render pixels stay visible squares (pixel filtering is what stage 1 is about);
  // shrunk ones are averaged.
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

GlTexture::~GlTexture() {
  gl_.DeleteTextures(1, &id_);
}

void GlTexture::upload(const DisplayImage& image) {
  if (image.width <= 0 || image.height <= 0) return;
  gl_.BindTexture(GL_TEXTURE_2D, id_);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  if (image.width != width_ || image.height != height_) {
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                   GL_UNSIGNED_BYTE, image.rgba.data());
    width_ = image.width;
    height_ = image.height;
  } else {
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.rgba.data());
  }
}

std::vector<uint8_t> readFramebuffer(const GlFunctions& gl, int width, int height) {
  std::vector<uint8_t> bottomUp(static_cast<size_t>(width) * height * 3);
  gl.PixelStorei(GL_PACK_ALIGNMENT, 1);
  gl.ReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
  std::vector<uint8_t> topDown(bottomUp.size());
  const size_t row = static_cast<size_t>(width) * 3;
  for (int y = 0; y < height; ++y)
    std::memcpy(&topDown[y * row], &bottomUp[(height - 1 - y) * row], row);
  return topDown;
}

void writeScreenshot(const std::string& path, int width, int height,
                     const std::vector<uint8_t>& rgb) {
  try {
    writeRaster(path, {width, height, {"R", "G", "B"}, {}}, true, rgb.data());
  } catch (const PathwayError& error) {
    throw PathwayError(std::string("cannot write a screenshot: ") + error.what());
  }
}

}  // namespace pathway
