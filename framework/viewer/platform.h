// The two ways the viewer gets a GL context and input: a GLFW window (window_glfw.cpp) or an
// OSMesa offscreen buffer (context_osmesa.cpp). The viewer draws the same frames into either.
#pragma once

#include <memory>
#include <vector>

#include "viewer/gl_functions.h"
#include "viewer/key_queue.h"

struct ImDrawData;

namespace pathway {

class Platform {
 public:
  virtual ~Platform() = default;

  virtual const GlFunctions& gl() const = 0;
  // After ImGui::CreateContext: sets up the ImGui platform and renderer backends.
  virtual void initImGui() = 0;
  virtual void shutdownImGui() = 0;

  virtual bool shouldClose() const = 0;
  virtual bool interactive() const = 0;  // has a user (input events) to wait for
  // Sleeps until input arrives, wake() is called, or `timeoutSeconds` pass.
  virtual void waitEvents(double timeoutSeconds) = 0;
  virtual void wake() = 0;      // any thread
  virtual void newFrame() = 0;  // before ImGui::NewFrame
  // Every key pressed since the last call, however briefly (an offscreen context has none).
  virtual std::vector<KeyPress> takeKeyPresses() { return {}; }
  virtual void renderDrawData(ImDrawData* data) = 0;
  virtual void present() = 0;
  virtual void framebufferSize(int& width, int& height) const = 0;
};

// Throws PathwayError with one clear message (use --headless or set DISPLAY) when there is no
// display or no usable OpenGL.
std::unique_ptr<Platform> createGlfwPlatform(int width, int height, const char* title);
std::unique_ptr<Platform> createOsmesaPlatform(int width, int height);

}  // namespace pathway
