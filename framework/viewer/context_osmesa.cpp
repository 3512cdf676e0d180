// The offscreen path: an OSMesa context (llvmpipe) rendering into memory, so the viewer can be
// drawn and screenshotted with no display. ImGui's OpenGL2 backend draws here: its direct gl*
// calls reach libOSMesa through gl_legacy_entry_points.cpp (see gl_functions.h). The OpenGL3
// backend cannot be used: its loader dlopens libGL, whose functions know nothing of OSMesa.
#include <backends/imgui_impl_opengl2.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <vector>

#include "core/error.h"
#include "viewer/osmesa_library.h"
#include "viewer/platform.h"

namespace pathway {
namespace {

class OsmesaPlatform : public Platform {
 public:
  OsmesaPlatform(int width, int height)
      : width_(width), height_(height), buffer_(static_cast<size_t>(width) * height * 4) {
    context_ = osmesa_.createContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!context_) throw PathwayError("OSMesa could not create an offscreen OpenGL context");
    if (!osmesa_.makeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, width, height)) {
      osmesa_.destroyContext(context_);
      throw PathwayError("OSMesa could not make its offscreen context current");
    }
    gl_.load(osmesa_.getProcAddress);
    last_ = std::chrono::steady_clock::now();
  }

  ~OsmesaPlatform() override { osmesa_.destroyContext(context_); }

  const GlFunctions& gl() const override { return gl_; }

  void initImGui() override {
    ImGuiIO& io = ImGui::GetIO();
    io.BackendPlatformName = "pathway_osmesa";
    io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
    if (!ImGui_ImplOpenGL2_Init()) throw PathwayError("ImGui could not draw with OSMesa");
  }
  void shutdownImGui() override { ImGui_ImplOpenGL2_Shutdown(); }

  bool shouldClose() const override { return false; }
  bool interactive() const override { return false; }

  void waitEvents(double timeoutSeconds) override {
    std::unique_lock<std::mutex> lock(mutex_);
    woken_.wait_for(lock, std::chrono::duration<double>(timeoutSeconds), [this] { return awake_; });
    awake_ = false;
  }
  void wake() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      awake_ = true;
    }
    woken_.notify_all();
  }

  void newFrame() override {
    ImGui_ImplOpenGL2_NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
    const auto now = std::chrono::steady_clock::now();
    io.DeltaTime = std::max(1e-4f, std::chrono::duration<float>(now - last_).count());
    last_ = now;
  }
  void renderDrawData(ImDrawData* data) override { ImGui_ImplOpenGL2_RenderDrawData(data); }
  void present() override { gl_.Finish(); }
  void framebufferSize(int& width, int& height) const override {
    width = width_;
    height = height_;
  }

 private:
  const OsmesaLibrary& osmesa_ = osmesaLibrary();
  int width_, height_;
  std::vector<unsigned char> buffer_;
  OSMesaContext context_ = nullptr;
  GlFunctions gl_;
  std::chrono::steady_clock::time_point last_;
  std::mutex mutex_;
  std::condition_variable woken_;
  bool awake_ = false;
};

}  // namespace

std::unique_ptr<Platform> createOsmesaPlatform(int width, int height) {
  return std::make_unique<OsmesaPlatform>(width, height);
}

}  // namespace pathway
