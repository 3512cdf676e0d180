#include "chart/chart_runner.h"

#include <tbb/info.h>

#include <cinttypes>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "core/error.h"
#include "core/number_format.h"
#include "core/stable_hash.h"
#include "core/text_output.h"
#include "engine/render_session.h"
#include "io/image_io.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const char* const kRunsHeader =
    "label,seed,spp,seconds,primary_rays,secondary_rays,shadow_rays,samples,invalid_samples,"
    "rel_mse,mse,key";

// Everything of a recipe that decides the image, as text (the seed and spp are added by callers).
std::string describeRecipe(const RenderRecipe& recipe) {
  const RenderSettings& s = recipe.settings;
  std::ostringstream out;
  out << recipe.integrator;
  const std::string params = recipe.params.describe();
  if (!params.empty()) out << " " << params;
  out << " earlier-stages=" << earlierStagesName(recipe.earlierStages)
      << " sampler=" << samplerTypeName(s.sampler) << " filter=" << filterTypeName(s.filter)
      << " filter-radius=" << s.filterRadiusPixels();
  return out.str();
}

struct ChartScene {
  Scene scene;
  std::unique_ptr<RayTracer> tracer;
  int width = 0, height = 0;
};

std::string machineDescription(int threads) {
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line, model = "unknown CPU";
  while (std::getline(cpuinfo, line)) {
    if (line.rfind("model name", 0) == 0 && line.find(':') != std::string::npos) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  const int used = threads > 0 ? threads : tbb::info::default_concurrency();
  return model + ", " + std::to_string(used) + " threads";
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::vector<std::string> splitCsvLine(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
      fields.back() += '"';
      ++i;
    } else if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

}  // namespace

std::string formatRunCsvLine(const ChartRun& run) {
  char numbers[512];
  const RayCounters& c = run.counters;
  std::snprintf(numbers, sizeof numbers,
                "%" PRIu64 ",%u,%.9g,%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",%" PRIu64 ",",
                run.seed, run.spp, run.seconds, c.primary, c.secondary, c.shadow, c.samples,
                c.invalidSamples);
  std::string line = csvField(run.label) + "," + numbers;
  if (run.error) {
    char errors[64];
    std::snprintf(errors, sizeof errors, "%.9g,%.9g", run.error->relMse, run.error->mse);
    line += errors;
  } else {
    line += ",";
  }
  return line + "," + run.key;
}

// A line of runs.csv back into a run; nothing when it is not one (a cache cut off mid-line).
std::optional<ChartRun> parseRunCsvLine(const std::string& line) {
  const std::vector<std::string> f = splitCsvLine(line);
  if (f.size() != 12 || f[11].size() != 16) return std::nullopt;
  try {
    ChartRun run;
    run.label = f[0];
    run.seed = std::stoull(f[1]);
    run.spp = static_cast<uint32_t>(std::stoul(f[2]));
    run.seconds = std::stod(f[3]);
    run.counters.primary = std::stoull(f[4]);
    run.counters.secondary = std::stoull(f[5]);
    run.counters.shadow = std::stoull(f[6]);
    run.counters.samples = std::stoull(f[7]);
    run.counters.invalidSamples = std::stoull(f[8]);
    if (!f[9].empty()) run.error = ImageError{std::stod(f[9]), std::stod(f[10])};
    run.key = f[11];
    return run;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

namespace {

// The measured renders of earlier runs, by key: the chart's own runs.csv and the cache's log.
std::map<std::string, ChartRun> loadCachedRuns(const fs::path& folder) {
  std::map<std::string, ChartRun> runs;
  for (const fs::path& file : {folder / "runs.csv", folder / "cache" / "runs.csv"}) {
    std::ifstream in(file);
    std::string line;
    size_t number = 0, skipped = 0;
    while (std::getline(in, line)) {
      if (++number == 1 && line == kRunsHeader) continue;
      if (auto run = parseRunCsvLine(line))
        runs[run->key] = *run;
      else
        ++skipped;
    }
    if (skipped > 0)
      std::fprintf(stderr, "pathway chart: warning: %s: %zu unreadable line(s) ignored\n",
                   file.c_str(), skipped);
  }
  return runs;
}

}  // namespace

ChartData runChart(const ChartSpec& spec, const ChartRunOptions& options) {
  spec.check();
  const fs::path folder(options.folder);
  std::error_code error;
  fs::create_directories(folder / "cache", error);
  if (!fs::is_directory(folder / "cache"))
    throw PathwayError(options.folder + ": cannot create the chart folder");

  // Scenes, each loaded once.
  std::map<std::string, ChartScene> scenes;
  for (const ChartConfig& config : spec.configs) {
    const std::string& path = spec.sceneOf(config);
    if (scenes.count(path)) continue;
    ChartScene& loaded = scenes[path];
    loaded.scene = loadScene(path, config.choices.sceneOptions());
    loaded.tracer = std::make_unique<RayTracer>(loaded.scene);
    loaded.width = spec.width;
    loaded.height = loaded.scene.imageHeight(spec.width);
  }

  // A reference renders its configuration with the wavefront version of a reference stage where
  // there is one (options.tracing).
  auto recipeOf = [&](const ChartConfig& config, uint32_t spp, uint64_t seed,
                      bool reference = false) {
    const ChartScene& scene = scenes.at(spec.sceneOf(config));
    RenderChoices choices = config.choices;
    if (reference) choices.integrator = referenceIntegratorFor(choices.integrator, options.tracing);
    return RenderRecipe(choices.builder()
                            .size(scene.width, scene.height)
                            .spp(spp, samplesPerProgressPass(spp))
                            .seed(seed)
                            .threads(options.threads));
  };
  auto keyOf = [&](const ChartConfig& config, const RenderRecipe& recipe,
                   const std::string& referenceKey) {
    const ChartScene& scene = scenes.at(spec.sceneOf(config));
    std::ostringstream text;
    text << "scene " << hexDigits(scene.tracer->sceneHash()) << " " << scene.width << "x"
         << scene.height << " " << describeRecipe(recipe) << " spp "
         << recipe.settings.samplesPerPixel << " seed " << recipe.settings.seed << " reference "
         << referenceKey;
    return hexDigits(stableHash(text.str()));
  };

  ChartData data;
  data.machine = machineDescription(options.threads);
  std::map<std::string, ChartRun> cached;
  if (!options.fresh) cached = loadCachedRuns(folder);

  // Plan: the references (one per reference configuration, at factor x the largest spp of the
  // configurations it serves) and the renders, noting which are cached.
  struct PlannedReference {
    const ChartConfig* config;
    uint32_t spp = 0;
    std::string key, exrPath, pngPath;
    bool cached = false;
  };
  std::map<std::string, PlannedReference> planned;  // by reference configuration label
  double plannedSamples = 0.0;
  if (spec.withReference) {
    for (const ChartConfig& config : spec.configs) {
      const ChartConfig& source = spec.referenceConfigOf(config);
      PlannedReference& reference = planned[source.label];
      reference.config = &source;
      reference.spp = std::max(reference.spp, spec.referenceFactor * spec.maxSppOf(config));
    }
    for (auto& [label, reference] : planned) {
      const RenderRecipe recipe = recipeOf(*reference.config, reference.spp, kReferenceSeed, true);
      reference.key = keyOf(*reference.config, recipe, "none");
      const fs::path base = folder / "cache" / ("reference-" + reference.key);
      reference.exrPath = base.string() + ".exr";
      reference.pngPath = base.string() + ".png";
      reference.cached = !options.fresh && fs::exists(reference.exrPath);
      const ChartScene& scene = scenes.at(spec.sceneOf(*reference.config));
      if (!reference.cached) plannedSamples += double(reference.spp) * scene.width * scene.height;
    }
  }
  struct PlannedRun {
    const ChartConfig* config;
    size_t index;  // into data.runs
    RenderRecipe recipe;
  };
  std::vector<PlannedRun> toRender;
  for (const ChartConfig& config : spec.configs) {
    const std::string referenceKey =
        spec.withReference ? planned.at(spec.referenceConfigOf(config).label).key : "none";
    data.descriptions.push_back(describeRecipe(recipeOf(config, 1, 0)) + " scene " +
                                spec.sceneOf(config));
    for (uint32_t spp = 1; spp <= spec.maxSppOf(config); spp *= 2) {
      for (int seed = 1; seed <= spec.seeds; ++seed) {
        const RenderRecipe recipe = recipeOf(config, spp, uint64_t(seed));
        ChartRun run;
        run.label = config.label;
        run.seed = uint64_t(seed);
        run.spp = spp;
        run.key = keyOf(config, recipe, referenceKey);
        const auto hit = cached.find(run.key);
        if (hit != cached.end()) {
          run = hit->second;
          run.label = config.label;  // the label may have changed; the render did not
        } else {
          toRender.push_back({&config, data.runs.size(), recipe});
          const ChartScene& scene = scenes.at(spec.sceneOf(config));
          plannedSamples += double(spp) * scene.width * scene.height;
        }
        data.runs.push_back(run);
      }
    }
  }

  double doneSamples = 0.0;
  auto report = [&](double samplesNow, const std::string& what) {
    if (options.progress && plannedSamples > 0.0)
      options.progress((doneSamples + samplesNow) / plannedSamples, what);
  };

  // References first: every render is compared with one.
  std::map<std::string, Image> referenceImages;  // by reference configuration label
  for (auto& [label, reference] : planned) {
    const ChartScene& scene = scenes.at(spec.sceneOf(*reference.config));
    if (reference.cached) {
      LoadedImage loaded = readImageFile(reference.exrPath);
      if (loaded.images.color.width != scene.width || loaded.images.color.height != scene.height)
        throw PathwayError(reference.exrPath + ": the cached reference has the wrong size");
      referenceImages[label] = std::move(loaded.images.color);
    } else {
      const RenderRecipe recipe = recipeOf(*reference.config, reference.spp, kReferenceSeed, true);
      const std::string what =
          "reference of \"" + label + "\", " + std::to_string(reference.spp) + " spp";
      const RenderResult result = runRender(*scene.tracer, recipe, [&](const RenderStats& stats) {
        report(double(stats.samplesPerPixel) * scene.width * scene.height, what);
      });
      doneSamples += double(reference.spp) * scene.width * scene.height;
      writeExr(reference.exrPath, result.images, result.metadata);
      writePng(reference.pngPath, result.images.color, 0.0f);
      referenceImages[label] = result.images.color;
    }
  }
  for (const ChartConfig& config : spec.configs) {
    if (!spec.withReference) break;
    const PlannedReference& reference = planned.at(spec.referenceConfigOf(config).label);
    const ChartScene& scene = scenes.at(spec.sceneOf(config));
    data.references.push_back({config.label, reference.key, reference.exrPath, reference.pngPath,
                               reference.spp, scene.width, scene.height});
  }

  // Then the renders, the lowest spp of every configuration first: a machine that slows down
  // part-way (another job starting) then disturbs every configuration alike.
  std::stable_sort(toRender.begin(), toRender.end(), [&](const PlannedRun& a, const PlannedRun& b) {
    return a.recipe.settings.samplesPerPixel < b.recipe.settings.samplesPerPixel;
  });
  const fs::path logPath = folder / "cache" / "runs.csv";
  const bool logIsNew = !fs::exists(logPath) || fs::file_size(logPath) == 0;
  std::ofstream log(logPath, std::ios::app);
  if (logIsNew) log << kRunsHeader << "\n";
  size_t renderedCount = 0;
  for (const PlannedRun& plan : toRender) {
    const ChartScene& scene = scenes.at(spec.sceneOf(*plan.config));
    ChartRun& run = data.runs[plan.index];
    const std::string what = "\"" + run.label + "\" " + std::to_string(run.spp) + " spp, render " +
                             std::to_string(++renderedCount) + "/" +
                             std::to_string(toRender.size());
    const RenderResult result = runRender(*scene.tracer, plan.recipe, [&](const RenderStats& s) {
      report(double(s.samplesPerPixel) * scene.width * scene.height, what);
    });
    doneSamples += double(run.spp) * scene.width * scene.height;
    run.seconds = result.stats.seconds;
    run.counters = result.stats.counters;
    if (spec.withReference)
      run.error = imageError(result.images.color,
                             referenceImages.at(spec.referenceConfigOf(*plan.config).label));
    log << formatRunCsvLine(run) << "\n" << std::flush;
  }

  // The chart's own data: exactly its runs, in order.
  std::string csv = std::string(kRunsHeader) + "\n";
  for (const ChartRun& run : data.runs) csv += formatRunCsvLine(run) + "\n";
  writeTextAtomically((folder / "runs.csv").string(), csv);
  return data;
}

}  // namespace pathway
