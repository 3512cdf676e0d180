// The error plot's data: per pane, the relMSE against the reference (chart/image_error.h) of each
// new image of the current render job, with its render time and spp, and the log-log axes the
// panel draws it on (panel_error_plot.cpp). Monte Carlo error falls as 1/time: a line of slope −1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "viewer/reference_image.h"
#include "viewer/render_worker.h"

namespace pathway {

struct ErrorPoint {
  double seconds = 0.0;  // the pane's render time so far (its job's passes)
  uint32_t spp = 0;
  double relMse = 0.0;
};

class ErrorHistory {
 public:
  // Measures a new image of the pane. An image of a later job starts the history afresh, one of
  // an earlier job (still shown while the new one renders) is ignored; one that cannot be
  // measured (another size, a stale reference) leaves a message instead of a point.
  // A measurement reads every pixel once: 0.6 ms at 512 x 512.
  void add(const LaneFrame& frame, const ReferenceImage& reference);
  // Forgets the points (a new reference: they measured against another one).
  void clear();
  // A new job was submitted for this pane (another view, V, B, ...): the plot shows its series
  // only, empty until its first image, instead of the old job's.
  void restart(uint64_t job, const std::string& integrator);

  uint64_t job() const { return job_; }
  const std::string& integrator() const { return integrator_; }      // of the newest image
  const std::vector<ErrorPoint>& points() const { return points_; }  // in time order
  const std::string& message() const { return message_; }  // why the newest image has no point

 private:
  uint64_t job_ = 0;
  std::string integrator_;
  std::vector<ErrorPoint> points_;
  std::string message_;
};

// A log10 axis over whole decades, from 10^first to 10^last (last > first).
struct LogAxis {
  int first = 0;
  int last = 1;

  double position(double value) const;  // 0 at 10^first, 1 at 10^last
};

// The smallest such axis holding every value in [lo, hi] (both > 0).
LogAxis logAxis(double lo, double hi);

// Tick labels: relMSE "1", "0.1", "0.01", "1e-3", ... and seconds "10 ms", "1 s", "100 s", ...
std::string decadeLabel(int exponent);
std::string secondsLabel(int exponent);

}  // namespace pathway
