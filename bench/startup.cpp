#include "startup.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.h"
#include "spawn.h"

namespace pathway::bench {
namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

SpawnedRun runPathway(const std::vector<std::string>& arguments) {
  std::vector<std::string> command = {PATHWAY_PROGRAM};
  command.insert(command.end(), arguments.begin(), arguments.end());
  SpawnedRun run = spawnCapturingStdout(command);
  if (!run.outcome.succeeded())
    throw PathwayError("pathway " + arguments.front() + " " + run.outcome.describe(0.0));
  return run;
}

// The value after `key` in the line `pathway render --timings` prints ("first ray 31.5,").
double timing(const std::string& output, const std::string& key) {
  const size_t at = output.find(key + " ");
  if (at == std::string::npos) throw PathwayError("no \"" + key + "\" in: " + output);
  return std::atof(output.c_str() + at + key.size() + 1);
}

}  // namespace

int benchStartup(int repeats) {
  const std::string image =
      (std::filesystem::temp_directory_path() / "pathway_bench_startup.exr").string();
  std::vector<double> help, firstRay, lastRay, written, whole;
  for (int i = 0; i < repeats; ++i) {
    help.push_back(runPathway({"render", "--help"}).seconds * 1e3);
    const SpawnedRun render =
        runPathway({"render", PATHWAY_DEFAULT_SCENE, "-i", "stage5@ref", "--width", "256", "--spp",
                    "64", "-p", "max-depth=5", "--timings", "-q", "-o", image});
    firstRay.push_back(timing(render.outcome.output, "first ray"));
    lastRay.push_back(timing(render.outcome.output, "last ray"));
    written.push_back(timing(render.outcome.output, "images written"));
    whole.push_back(render.seconds * 1e3);
  }
  std::filesystem::remove(image);
  std::printf("%s, median of %d runs, ms from launch:\n", PATHWAY_PROGRAM, repeats);
  std::printf("  pathway render --help, whole process        %8.1f\n", median(help));
  std::printf("  stage5@ref 256x256 64 spp to EXR: first ray  %8.1f\n", median(firstRay));
  std::printf("                                    last ray   %8.1f\n", median(lastRay));
  std::printf("                                    EXR written%8.1f\n", median(written));
  std::printf("                                    process end%8.1f\n", median(whole));
  return 0;
}

}  // namespace pathway::bench
