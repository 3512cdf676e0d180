// The GL side of showing images: a texture per pane (drawn by ImGui's draw list, so both GL
// backends draw it the same way) and reading the finished frame back for a screenshot.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "viewer/display_image.h"
#include "viewer/gl_functions.h"

namespace pathway {

class GlTexture {
 public:
  explicit GlTexture(const GlFunctions& gl);
  ~GlTexture();
  GlTexture(const GlTexture&) = delete;
  GlTexture& operator=(const GlTexture&) = delete;

  void upload(const DisplayImage& image);
  void* imguiId() const { return reinterpret_cast<void*>(static_cast<uintptr_t>(id_)); }
  int width() const { return width_; }
  int height() const { return height_; }

 private:
  const GlFunctions& gl_;
  GLuint id_ = 0;
  int width_ = 0, height_ = 0;
};

// The current framebuffer as RGB, rows top to bottom (GL's are bottom to top).
std::vector<uint8_t> readFramebuffer(const GlFunctions& gl, int width, int height);
// Writes 8-bit RGB rows to a PNG (or another format the image-file module knows); throws
// PathwayError on failure.
void writeScreenshot(const std::string& path, int width, int height,
                     const std::vector<uint8_t>& rgb);

}  // namespace pathway
