// `pathway chart`: speed against accuracy (docs/charts.md). Renders each configuration at spp
// 1, 2, 4 ... with several seeds, compares with a cached high-spp reference, and writes the data
// (runs.csv, summary.csv/json/md) and the chart (chart.png/svg, drawn by scripts/draw_chart.py).
#include <cstdio>
#include <filesystem>

#include "app/commands.h"
#include "app/progress_bar.h"
#include "app/shared_options.h"
#include "chart/chart_summary.h"
#include "chart/filter_profiles.h"
#include "core/child_process.h"
#include "core/error.h"
#include "core/text_output.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kDrawScript = PATHWAY_SOURCE_DIR "/scripts/draw_chart.py";

// Debian's Python, which python3-matplotlib installs into, even when another python3 (pyenv,
// conda) comes first on PATH.
std::string python() {
  return fs::exists("/usr/bin/python3") ? "/usr/bin/python3" : "python3";
}

struct ChartOptions {
  ChartSpec spec;
  std::vector<std::string> configs;
  std::string out = "chart";
  int threads = setting::kThreads.defaultAs<int>();
  bool fresh = false;
  bool singleRay = false;
  bool draw = true;
  bool quiet = false;
  std::string filterProfiles;  // a CSV path: tabulate the filters and stop
};

// Draws the chart with matplotlib; throws PathwayError with the script's output when it fails.
void drawChart(const std::string& folder) {
  const std::string log = (fs::path(folder) / "cache" / "draw.log").string();
  const ChildOutcome outcome = runChild({python(), kDrawScript, "convergence", folder}, 600.0, log);
  if (!outcome.succeeded())
    throw PathwayError("drawing the chart failed (" + python() + " " + kDrawScript +
                       " convergence " + folder + " " + outcome.describe(600.0) + "):\n" +
                       outcome.output);
}

int run(ChartOptions& options) {
  if (!options.filterProfiles.empty()) {
    Variant used = Variant::Student;
    writeTextAtomically(options.filterProfiles, filterProfilesCsv(&used));
    std::printf("wrote %s (the %s stage 1's filter functions)\n", options.filterProfiles.c_str(),
                variantName(used));
    return 0;
  }
  ChartSpec& spec = options.spec;
  for (const std::string& text : options.configs) spec.configs.push_back(parseChartConfig(text));
  spec.check();  // before anything is loaded or rendered

  ProgressBar progress(!options.quiet);
  ChartRunOptions runOptions;
  runOptions.folder = options.out;
  runOptions.threads = options.threads;
  runOptions.fresh = options.fresh;
  if (options.singleRay) runOptions.tracing = ReferenceTracing::SingleRay;
  runOptions.progress = [&](double fraction, const std::string& what) {
    progress.update(fraction, what.c_str());
  };
  const ChartData data = runChart(spec, runOptions);
  progress.finish();

  const ChartSummary summary = summarizeChart(spec, data);
  const fs::path folder(options.out);
  writeTextAtomically((folder / "summary.json").string(), summaryJson(spec, summary));
  writeTextAtomically((folder / "summary.csv").string(), summaryCsv(summary));
  const std::string table = summaryMarkdown(summary);
  writeTextAtomically((folder / "summary.md").string(), table);
  if (options.draw) drawChart(options.out);
  if (!options.quiet) {
    std::printf("%s\n", table.c_str());
    std::printf("wrote %s/{runs.csv,summary.json,summary.csv,summary.md%s}\n", options.out.c_str(),
                options.draw ? ",chart.png,chart.svg" : "");
  }
  return 0;
}

}  // namespace

Command addChartCommand(CLI::App& app) {
  auto options = std::make_shared<ChartOptions>();
  options->spec.scene = PATHWAY_DEFAULT_SCENE;
  CLI::App* chart = app.add_subcommand("chart", "Chart error against time and rays (convergence)");
  chart->footer(
      "A configuration is \"LABEL: INTEGRATOR [key=value ...]\" (a value with spaces in double\n"
      "quotes); keys: sampler, filter, filter-radius, scene, max-spp, reference (the label whose\n"
      "recipe renders this one's reference), group and x (for sweep figures); other keys are\n"
      "integrator parameters.\n\n"
      "Examples:\n"
      "  pathway chart scenes/cornell_box.gltf -o out/samplers \\\n"
      "      -c 'independent: stage3@ref sampler=independent' \\\n"
      "      -c 'sobol: stage3@ref sampler=sobol reference=independent'\n"
      "  pathway chart --filter-profiles profiles.csv\n"
      "The ready-made chart sets of the course: scripts/charts (docs/charts.md).");
  chart->add_option("scene", options->spec.scene, "glTF scene of configurations without scene=")
      ->capture_default_str();
  chart->add_option("--title", options->spec.title, "Title over the chart");
  chart->add_option("-c,--config", options->configs, "A configuration to chart (repeatable)");
  chart
      ->add_option("-o,--out", options->out,
                   "Folder for the data and charts; its cache/ keeps references and renders")
      ->capture_default_str();
  addOption(*chart, setting::kChartWidth, options->spec.width);
  addOption(*chart, setting::kChartMaxSpp, options->spec.maxSpp);
  addOption(*chart, setting::kChartSeeds, options->spec.seeds);
  addOption(*chart, setting::kReferenceFactor, options->spec.referenceFactor);
  addOption(*chart, setting::kThreads, options->threads);
  chart->add_flag("--no-reference{false}", options->spec.withReference,
                  "Measure time and rays only (no reference, no errors)");
  chart->add_flag("--fresh", options->fresh, "Render everything again, ignoring the cache");
  chart->add_flag("--single-ray", options->singleRay,
                  "Render the references with stageN@ref, one ray at a time, even where the "
                  "faster stageN@fast exists");
  chart->add_flag("--no-draw{false}", options->draw, "Write the data only, no PNG/SVG");
  chart->add_flag("-q,--quiet", options->quiet, "No progress bar or table");
  chart->add_option("--filter-profiles", options->filterProfiles,
                    "Write the filters' 1D profiles from stage 1's code to this CSV, then exit");
  return {chart, [options] { return run(*options); }};
}

}  // namespace pathway
