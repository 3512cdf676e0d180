#include "viewer/error_plot.h"

#include <cmath>

#include "chart/image_error.h"

namespace pathway {

void ErrorHistory::add(const LaneFrame& frame, const ReferenceImage& reference) {
  if (frame.job < job_) return;  // an image of a job since replaced
  if (frame.job != job_) {
    clear();
    job_ = frame.job;
  }
  integrator_ = frame.integrator;
  message_.clear();
  if (!frame.error.empty() || frame.images.color.pixels.empty()) return;  // the pane says why
  message_ = referenceProblem(reference, frame);
  if (!message_.empty()) return;
  const uint32_t spp = frame.stats.samplesPerPixel;
  if (!points_.empty() && spp <= points_.back().spp) return;  // measured already
  points_.push_back(
      {frame.stats.seconds, spp, imageError(frame.images.color, reference.image).relMse});
}

void ErrorHistory::clear() {
  points_.clear();
  message_.clear();
}

void ErrorHistory::restart(uint64_t job, const std::string& integrator) {
  clear();
  job_ = job;
  integrator_ = integrator;
}

double LogAxis::position(double value) const {
  return (std::log10(value) - first) / (last - first);
}

LogAxis logAxis(double lo, double hi) {
  LogAxis axis;
  axis.first = static_cast<int>(std::floor(std::log10(lo)));
  axis.last = static_cast<int>(std::ceil(std::log10(hi)));
  if (axis.last <= axis.first) axis.last = axis.first + 1;  // one value, or a power of ten
  return axis;
}

std::string decadeLabel(int exponent) {
  if (exponent >= 0 && exponent <= 2) return std::string("1") + std::string(exponent, '0');
  if (exponent < 0 && exponent >= -2) return "0." + std::string(-exponent - 1, '0') + "1";
  return "1e" + std::to_string(exponent);
}

std::string secondsLabel(int exponent) {
  if (exponent >= 0) return "1" + std::string(exponent, '0') + " s";
  if (exponent >= -3) return "1" + std::string(exponent + 3, '0') + " ms";
  return "1e" + std::to_string(exponent) + " s";
}

}  // namespace pathway
