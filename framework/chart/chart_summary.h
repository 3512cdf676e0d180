// What a chart's renders say: per configuration and spp the median and spread over seeds, the
// convergence slope fitted on log-log axes, efficiency 1/(relMSE·t), the time to reach a target
// relMSE, and every configuration's error at one common time and at one common ray count.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "chart/chart_runner.h"

namespace pathway {

// The relMSE whose time to reach a chart reports.
inline constexpr double kTargetRelMse = 1e-3;

struct ChartPoint {
  uint32_t spp = 0;
  int renders = 0;
  double seconds = 0.0, secondsLow = 0.0, secondsHigh = 0.0;  // median, min, max over seeds
  double rays = 0.0;                                          // median total rays
  // Errors: median, min and max over seeds; absent without a reference.
  std::optional<double> relMse, relMseLow, relMseHigh, mse;
  std::optional<double> efficiency;  // 1 / (relMSE · seconds), medians
};

// log y = intercept + slope · log x, least squares over points with spp in [fromSpp, toSpp].
struct LogLogFit {
  double slope = 0.0, intercept = 0.0;
  uint32_t fromSpp = 0, toSpp = 0;
  double at(double x) const;  // the fitted y at x
};

// A value read off a line at a chosen x: between two measured points (log-log interpolation) or,
// outside them, from the fit.
struct ReadOff {
  double value = 0.0;
  bool extrapolated = false;
  bool atMost = false;  // the line was already there at its first point: the value is a bound
};

// The time to the target relMSE is not extrapolated along fits flatter than this: a line that
// barely falls says nothing about when it would reach a far-off error.
inline constexpr double kSteepestUnextrapolatedSlope = -0.5;

struct ChartLine {
  const ChartConfig* config = nullptr;
  std::string description;  // the full recipe
  const ChartReference* reference = nullptr;
  std::vector<ChartPoint> points;  // spp ascending
  double raysPerSample = 0.0;      // total rays over camera samples, all renders
  std::optional<LogLogFit> relMseBySpp, relMseBySeconds, mseBySeconds;
  std::optional<ReadOff> secondsToTarget;  // time to kTargetRelMse
};

struct ChartSummary {
  std::string machine;
  std::vector<ChartLine> lines;
  // The longest time / most rays that every line reached, and each line's error there.
  double equalSeconds = 0.0, equalRays = 0.0;
  std::vector<ReadOff> relMseAtEqualSeconds, rmseAtEqualSeconds, relMseAtEqualRays, rmseAtEqualRays;
};

ChartSummary summarizeChart(const ChartSpec& spec, const ChartData& data);

// summary.json (everything, for the drawing script), summary.csv (a row per line and spp) and
// summary.md (the efficiency table and slopes, for people).
std::string summaryJson(const ChartSpec& spec, const ChartSummary& summary);
std::string summaryCsv(const ChartSummary& summary);
std::string summaryMarkdown(const ChartSummary& summary);

}  // namespace pathway
