// The windowed path: GLFW creates the window and its GLX context (GLFW dlopens libGL itself),
// ImGui's GLFW backend feeds it input, and its OpenGL3 backend draws (it loads its GL functions
// through its own dlopen loader, so it never calls the program's own gl* symbols, which forward to
// libOSMesa: gl_legacy_entry_points.cpp).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdlib>
#include <string>

#include "core/error.h"
#include "viewer/platform.h"

namespace pathway {
namespace {

std::string lastGlfwError;

void recordGlfwError(int, const char* description) {
  lastGlfwError = description;
}

PathwayError noDisplay(const std::string& why) {
  return PathwayError("cannot open a window: " + why +
                      ". Run 'pathway view --headless --screenshot out.png' to draw the viewer "
                      "offscreen, or set DISPLAY to an X server (e.g. run it under xvfb-run).");
}

bool hasEnv(const char* name) {
  const char* value = std::getenv(name);
  return value && *value;
}

class GlfwPlatform : public Platform {
 public:
  GlfwPlatform(int width, int height, const char* title) {
    if (!hasEnv("DISPLAY") && !hasEnv("WAYLAND_DISPLAY"))
      throw noDisplay("no display (DISPLAY is not set)");
    glfwSetErrorCallback(recordGlfwError);
    if (!glfwInit()) throw noDisplay("GLFW could not start (" + lastGlfwError + ")");
    window_ = glfwCreateWindow(width, height, title, nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw noDisplay("no OpenGL window (" + lastGlfwError + ")");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    gl_.load(glfwGetProcAddress);
  }

  ~GlfwPlatform() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }

  const GlFunctions& gl() const override { return gl_; }

  void initImGui() override {
    // Ours first: ImGui's backend installs its callbacks over it and calls it from them, so
    // ImGui's own keyboard input (text fields, navigation) works as before.
    glfwSetWindowUserPointer(window_, &keys_);
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int, int action, int mods) {
      static_cast<KeyQueue*>(glfwGetWindowUserPointer(window))->onKey(key, action, mods);
    });
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    if (!ImGui_ImplOpenGL3_Init("#version 130")) {
      ImGui_ImplGlfw_Shutdown();
      throw noDisplay("OpenGL 3.0 is not available for the window");
    }
  }

  void shutdownImGui() override {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
  }

  bool shouldClose() const override { return glfwWindowShouldClose(window_); }
  bool interactive() const override { return true; }
  void waitEvents(double timeoutSeconds) override { glfwWaitEventsTimeout(timeoutSeconds); }
  void wake() override { glfwPostEmptyEvent(); }

  void newFrame() override {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
  }
  std::vector<KeyPress> takeKeyPresses() override { return keys_.take(); }
  void renderDrawData(ImDrawData* data) override { ImGui_ImplOpenGL3_RenderDrawData(data); }
  void present() override { glfwSwapBuffers(window_); }
  void framebufferSize(int& width, int& height) const override {
    glfwGetFramebufferSize(window_, &width, &height);
  }

 private:
  GLFWwindow* window_ = nullptr;
  GlFunctions gl_;
  KeyQueue keys_;
};

}  // namespace

std::unique_ptr<Platform> createGlfwPlatform(int width, int height, const char* title) {
  return std::make_unique<GlfwPlatform>(width, height, title);
}

}  // namespace pathway
