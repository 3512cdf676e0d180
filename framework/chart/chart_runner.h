// Renders what a chart measures: each configuration's reference (made on demand, cached as EXR
// under the chart's folder) and, for every spp 2^0 ... 2^k and every seed, one render whose wall
// time, exact ray counts and error against the reference it records. Renders already measured
// for the same recipe, scene content and reference are reused, so a rerun only renders what is new.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "chart/chart_spec.h"
#include "chart/image_error.h"
#include "core/ray_counters.h"
#include "render/integrator_registry.h"

namespace pathway {

struct ChartRun {
  std::string label;  // the configuration
  uint64_t seed = 0;
  uint32_t spp = 0;
  double seconds = 0.0;  // wall time of the render's passes
  RayCounters counters;
  std::optional<ImageError> error;  // none in a chart without references
  std::string key;                  // what was rendered, hashed: the cache's index
};

struct ChartReference {
  std::string label;  // the configuration it serves
  std::string key;
  std::string exrPath, pngPath;
  uint32_t spp = 0;
  int width = 0, height = 0;
};

struct ChartData {
  std::vector<ChartRun> runs;              // in configuration order, then spp, then seed
  std::vector<ChartReference> references;  // one per configuration, when the chart has them
  std::vector<std::string> descriptions;   // per configuration: its full recipe, as text
  std::string machine;                     // CPU and thread count the times were taken on
};

struct ChartRunOptions {
  std::string folder;  // the chart's folder: runs.csv and the cache/ beneath it
  int threads = 0;     // 0: all cores
  bool fresh = false;  // ignore what is cached and render everything again
  ReferenceTracing tracing = ReferenceTracing::Fastest;  // how the references render
  // Progress: the fraction of the planned samples done, and what is rendering.
  std::function<void(double, const std::string&)> progress;
};

// Checks the spec, then renders what is not cached. Throws PathwayError for bad input (unknown
// integrator, unreadable scene, a folder it cannot write).
ChartData runChart(const ChartSpec& spec, const ChartRunOptions& options);

// One line of runs.csv, and back (nothing for a line that is not one, e.g. cut off mid-write).
std::string formatRunCsvLine(const ChartRun& run);
std::optional<ChartRun> parseRunCsvLine(const std::string& line);

}  // namespace pathway
