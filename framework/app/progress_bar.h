// A one-line progress bar on stderr, shown only once a render has run for a second, and redrawn
// at most ten times a second (a chart reports thousands of small steps).
#pragma once

#include <chrono>
#include <cstdio>

namespace pathway {

class ProgressBar {
 public:
  explicit ProgressBar(bool enabled)
      : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}
  ~ProgressBar() { finish(); }

  void update(double fraction, const char* label) {
    const double elapsed = seconds();
    if (!enabled_ || elapsed < 1.0 || (elapsed < lastDrawn_ + 0.1 && fraction < 1.0)) return;
    lastDrawn_ = elapsed;
    constexpr int kWidth = 30;
    const int filled = static_cast<int>(fraction * kWidth + 0.5);
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    std::fprintf(stderr, "\r[%.*s%*s] %5.1f%%  %s  %.1f s, %.1f s left ", filled,
                 "##############################", kWidth - filled, "", 100.0 * fraction, label,
                 elapsed, eta);
    std::fflush(stderr);
    shown_ = true;
  }
  void finish() {
    if (shown_) std::fprintf(stderr, "\n");
    shown_ = false;
  }
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  bool enabled_;
  bool shown_ = false;
  double lastDrawn_ = -1.0;  // seconds() at the last redraw
  std::chrono::steady_clock::time_point start_;
};

}  // namespace pathway
