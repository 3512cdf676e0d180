#include "growth.h"

#include <tbb/info.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <memory>
#include <sstream>

#include "bench_kit.h"
#include "core/child_process.h"
#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "sampling/pcg32.h"
#include "scene/embree.h"
#include "scene/gltf_loader.h"
#include "spawn.h"

namespace pathway::bench {
namespace {

// ---- Output: tables on stdout as they are measured, the same numbers as CSV files. ----

std::string number(double value, int digits = 6) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, value);
  return text;
}

std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

using CsvRows = std::vector<std::vector<std::string>>;

// Writes `rows` (the header first) to DIR/NAME; nothing when no output folder was asked for.
void writeCsv(const std::string& dir, const std::string& name, const CsvRows& rows) {
  if (dir.empty()) return;
  const std::string path = (std::filesystem::path(dir) / name).string();
  std::ofstream out(path);
  for (const auto& row : rows) {
    for (size_t i = 0; i < row.size(); ++i) out << (i ? "," : "") << csvField(row[i]);
    out << '\n';
  }
  out.close();
  if (!out) throw PathwayError(path + ": cannot write");
}

// Least-squares slope of y against x.
double fittedSlope(const std::vector<double>& x, const std::vector<double>& y) {
  const double n = static_cast<double>(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < x.size(); ++i) {
    sx += x[i], sy += y[i], sxx += x[i] * x[i], sxy += x[i] * y[i];
  }
  const double denominator = n * sxx - sx * sx;
  return denominator != 0.0 ? (n * sxy - sx * sy) / denominator : 0.0;
}

std::vector<double> logOf(const std::vector<double>& values) {
  std::vector<double> logs;
  for (double v : values) logs.push_back(std::log(v));
  return logs;
}

// ---- The machine, for the tables' headers and the charts' titles. ----

std::string cpuModel() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      const size_t start = line.find_first_not_of(" \t", line.find(':') + 1);
      if (start != std::string::npos) return line.substr(start);
    }
  }
  return "unknown CPU";
}

// "L1d 48K, L2 2048K, L3 491520K": the data caches of the first CPU, as Linux reports them.
std::string dataCaches() {
  std::string caches;
  for (int index = 0;; ++index) {
    const std::string dir = "/sys/devices/system/cpu/cpu0/cache/index" + std::to_string(index);
    std::ifstream levelFile(dir + "/level"), typeFile(dir + "/type"), sizeFile(dir + "/size");
    std::string level, type, size;
    if (!(levelFile >> level) || !(typeFile >> type) || !(sizeFile >> size)) break;
    if (type == "Instruction") continue;
    caches += (caches.empty() ? "L" : ", L") + level + (type == "Data" ? "d " : " ") + size;
  }
  return caches.empty() ? "unknown" : caches;
}

// A value in kB from /proc/meminfo or /proc/self/status ("MemTotal:", "VmHWM:"), in bytes.
long procKilobytes(const char* file, const std::string& key) {
  std::ifstream in(file);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key, 0) == 0) return std::atol(line.c_str() + key.size()) * 1024;
  }
  return 0;
}

std::string utcNow() {
  const std::time_t now = std::time(nullptr);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

// ---- a and b: every stage against raw Embree, and on 1 and 2 threads. ----

struct Rates {
  double renderer = 0.0;  // Mrays/s
  double raw = 0.0;       // Mrays/s, the same rays through raw Embree
};

int cappedThreads(int threads) {
  return std::min(threads, tbb::info::default_concurrency());
}

// One stage's renderer and raw replay, ready to time on every thread count measured.
struct StageTimers {
  std::string label;
  uint32_t spp = 0;
  std::vector<LoggedRay> log;
  std::map<int, std::unique_ptr<PassTimer>> passes;     // by thread count
  std::map<int, std::unique_ptr<ReplayTimer>> replays;  // by thread count
  std::map<int, double> bestPass, bestReplay;           // seconds, by thread count
};

void benchStagesAndThreads(const Scene& scene, RayTracer& tracer, const GrowthOptions& options) {
  const int cores = tbb::info::default_concurrency();
  const int one = 1, two = cappedThreads(2);
  std::printf(
      "a. Every stage against raw Embree on the same rays: %dx%d, %d threads, best of %d passes\n"
      "   after a warm-up; raw: the pass's rays, recorded, traced by rtcIntersect1/rtcOccluded1.\n"
      "   Each stage, thread count, renderer and raw replay is timed once per round, %d rounds:\n"
      "   a busy spell of the machine costs each entry one round, not all of its runs\n",
      options.width, options.width, cores, options.repeats, options.repeats);
  std::fflush(stdout);
  const RawEmbree raw(scene);
  std::vector<std::unique_ptr<StageTimers>> stages;  // pointers: the replays refer to the logs
  for (const StageCase& c : kStageCases) {
    auto& stage = *stages.emplace_back(std::make_unique<StageTimers>());
    stage.label = caseLabel(c.integrator, c.params);
    stage.spp = c.spp;
    stage.log = recordRays(scene, tracer, c.integrator, c.params, options.width, c.spp);
    for (int threads : {one, two, cores}) {
      if (stage.passes.count(threads)) continue;
      stage.passes[threads] = std::make_unique<PassTimer>(
          scene, tracer, c.integrator, c.params, options.width, c.spp, options.repeats, threads);
      stage.replays[threads] = std::make_unique<ReplayTimer>(raw, stage.log, threads);
      stage.bestPass[threads] = stage.bestReplay[threads] = 1e30;
    }
  }
  for (int round = 0; round < options.repeats; ++round) {
    for (auto& stage : stages) {
      for (auto& [threads, pass] : stage->passes) {
        stage->bestPass[threads] = std::min(stage->bestPass[threads], pass->timePass());
        stage->bestReplay[threads] =
            std::min(stage->bestReplay[threads], stage->replays[threads]->timeReplay());
      }
    }
  }

  CsvRows stageRows = {
      {"integrator", "rays_per_sample", "mrays_per_s", "raw_mrays_per_s", "ratio"}};
  CsvRows threadRows = {{"integrator", "threads_low", "threads_high", "mrays_per_s_low",
                         "mrays_per_s_high", "speedup", "raw_mrays_per_s_low",
                         "raw_mrays_per_s_high", "raw_speedup"}};
  std::printf("%-22s %12s %10s %12s %8s\n", "integrator", "rays/sample", "Mrays/s", "raw Mrays/s",
              "ratio");
  std::vector<std::string> threadLines;
  for (const auto& stage : stages) {
    // Exact counts: the same for every pass and thread count.
    const uint64_t raysPerPass = stage->passes[cores]->raysPerPass();
    auto rates = [&](int threads) {
      return Rates{raysPerPass / stage->bestPass[threads] * 1e-6,
                   stage->log.size() / stage->bestReplay[threads] * 1e-6};
    };
    const Rates all = rates(cores), low = rates(one), high = rates(two);
    const double raysPerSample =
        double(raysPerPass) / (double(options.width) * options.width * stage->spp);
    const char* label = stage->label.c_str();
    std::printf("%-22s %12.2f %10.2f %12.2f %8.2f\n", label, raysPerSample, all.renderer, all.raw,
                all.renderer / all.raw);
    stageRows.push_back({label, number(raysPerSample, 4), number(all.renderer, 4),
                         number(all.raw, 4), number(all.renderer / all.raw, 4)});
    char line[256];
    std::snprintf(line, sizeof line, "%-22s %10.2f %10.2f %9.2f %10.2f %10.2f %9.2f", label,
                  low.renderer, high.renderer, high.renderer / low.renderer, low.raw, high.raw,
                  high.raw / low.raw);
    threadLines.push_back(line);
    threadRows.push_back({label, std::to_string(one), std::to_string(two), number(low.renderer, 4),
                          number(high.renderer, 4), number(high.renderer / low.renderer, 4),
                          number(low.raw, 4), number(high.raw, 4), number(high.raw / low.raw, 4)});
  }
  writeCsv(options.outDir, "stages.csv", stageRows);

  std::printf(
      "\nb. Thread scaling (the rounds of a): renderer with settings.threads = %d and %d;\n"
      "   raw Embree replay in a %d- and a %d-thread task arena\n",
      one, two, one, two);
  const std::string low = "Mrays/s " + std::to_string(one), high = "Mrays/s " + std::to_string(two);
  std::printf("%-22s %10s %10s %9s %10s %10s %9s\n", "integrator", low.c_str(), high.c_str(),
              "speed-up", ("raw " + std::to_string(one)).c_str(),
              ("raw " + std::to_string(two)).c_str(), "speed-up");
  for (const std::string& line : threadLines) std::printf("%s\n", line.c_str());
  std::fflush(stdout);
  writeCsv(options.outDir, "threads.csv", threadRows);
}

// ---- c: cost against samples per pixel. ----

// Small: the largest render, 64 spp of stage 5, stays near a second.
constexpr int kSppSide = 128;

void benchSpp(const Scene& scene, const RayTracer& tracer, const GrowthOptions& options) {
  const uint32_t sppValues[] = {1, 2, 4, 8, 16, 32, 64};
  std::printf(
      "\nc. Cost against samples per pixel: whole renders (runRender) at %dx%d, all cores, "
      "best of %d rounds over every spp\n",
      kSppSide, kSppSide, options.repeats);
  std::printf("%-22s %5s %10s %12s %12s %10s\n", "integrator", "spp", "seconds", "rays",
              "rays/(px*spp)", "Mrays/s");
  CsvRows rows = {{"integrator", "spp", "seconds", "rays", "mrays_per_s"}};
  std::vector<std::string> fits;
  const Camera camera(scene, kSppSide, kSppSide);
  for (const char* integrator : {"stage3@ref", "stage5@ref"}) {
    // One sample per pass: the recipe's default, so time grows with spp as the passes do.
    RenderRecipe recipe = RecipeBuilder(integrator).size(kSppSide, kSppSide);
    // Every spp once per round, so that a busy moment of the machine bends no part of the curve
    // more than another.
    std::vector<double> spps(std::begin(sppValues), std::end(sppValues));
    std::vector<double> seconds(spps.size(), 1e30);
    std::vector<uint64_t> rays(spps.size());
    for (int round = 0; round < options.repeats; ++round) {
      for (size_t k = 0; k < spps.size(); ++k) {
        recipe.settings.samplesPerPixel = sppValues[k];
        seconds[k] = std::min(seconds[k], secondsOf([&] {
                                rays[k] =
                                    runRender(tracer, camera, recipe).stats.counters.totalRays();
                              }));
      }
    }
    for (size_t k = 0; k < spps.size(); ++k) {
      const double mrays = rays[k] / seconds[k] * 1e-6;
      std::printf("%-22s %5u %10.4f %12llu %12.3f %10.2f\n", integrator, sppValues[k], seconds[k],
                  static_cast<unsigned long long>(rays[k]),
                  double(rays[k]) / (kSppSide * kSppSide * sppValues[k]), mrays);
      rows.push_back({integrator, std::to_string(sppValues[k]), number(seconds[k]),
                      std::to_string(rays[k]), number(mrays, 4)});
    }
    std::fflush(stdout);
    char fit[160];
    std::snprintf(fit, sizeof fit, "%s: seconds ~ spp^%.3f", integrator,
                  fittedSlope(logOf(spps), logOf(seconds)));
    fits.push_back(fit);
  }
  std::printf("fitted exponent (least squares on log-log, 1 = linear):");
  for (const std::string& fit : fits) std::printf("  %s", fit.c_str());
  std::printf("\n");
  writeCsv(options.outDir, "spp.csv", rows);
}

// ---- d: BVH growth on generated grids, each in a child process. ----

// The height field of scenes/generate.py --grid: n x n cells over [-1, 1]^2, 2 n^2 triangles,
// albedo 0.8 under a white sky, seen from above at an angle. Built in memory: 10M triangles
// through glTF would take minutes.
Scene gridScene(int cells) {
  Scene scene;
  scene.sourcePath = "generated grid of " + std::to_string(2ull * cells * cells) + " triangles";
  Material grey;
  grey.name = "grid";
  grey.baseColor = Color(0.8f);
  scene.materials = {grey};
  scene.background = Color(1.0f);
  Mesh mesh;
  mesh.name = "grid";
  const uint32_t row = static_cast<uint32_t>(cells) + 1;
  mesh.positions.reserve(size_t(row) * row);
  for (uint32_t j = 0; j < row; ++j) {
    const float z = -1.0f + 2.0f * j / cells;
    for (uint32_t i = 0; i < row; ++i) {
      const float x = -1.0f + 2.0f * i / cells;
      mesh.positions.emplace_back(x, 0.05f * std::sin(7.0f * x) * std::cos(5.0f * z), z);
      scene.bounds.extend(mesh.positions.back());
    }
  }
  mesh.triangles.reserve(2 * size_t(cells) * cells);
  for (uint32_t j = 0; j + 1 < row; ++j) {
    for (uint32_t i = 0; i + 1 < row; ++i) {
      const uint32_t v = j * row + i;  // counter-clockwise seen from +y
      mesh.triangles.emplace_back(v, v + row, v + row + 1);
      mesh.triangles.emplace_back(v, v + row + 1, v + 1);
    }
  }
  scene.meshes.push_back(std::move(mesh));
  CameraPlacement camera;
  camera.yfov = 0.9f;
  camera.cameraToWorld = glm::inverse(glm::lookAt(Vec3(0, 1.5f, 1.5f), Vec3(0), Vec3(0, 1, 0)));
  scene.camera = camera;
  return scene;
}

struct GridResult {
  std::map<std::string, double> values;  // by the child's key
  double operator[](const std::string& key) const {
    const auto it = values.find(key);
    if (it == values.end()) throw PathwayError("grid child: no value for " + key);
    return it->second;
  }
};

// Runs this program as a child that measures one grid; its stdout comes back through a pipe.
GridResult measureGridInChild(int cells, int width, int repeats) {
  const SpawnedRun run =
      spawnCapturingStdout({currentExecutable(), kGrowthChildMode, std::to_string(cells),
                            std::to_string(width), std::to_string(repeats)});
  const ChildOutcome& outcome = run.outcome;
  if (!outcome.succeeded())
    throw PathwayError("measuring the grid of " + std::to_string(2ull * cells * cells) +
                       " triangles: its child process " + outcome.describe(0.0));
  const std::string& output = outcome.output;
  GridResult result;
  std::istringstream words(output);
  for (std::string word; words >> word;) {
    const size_t equals = word.find('=');
    if (equals != std::string::npos)
      result.values[word.substr(0, equals)] = std::atof(word.c_str() + equals + 1);
  }
  return result;
}

// Decades from 10k up to the cap, and the cap itself when it falls between two decades.
std::vector<uint64_t> gridSizes(uint64_t maxTriangles) {
  std::vector<uint64_t> sizes;
  for (uint64_t n = kMinGrowthTriangles; n <= maxTriangles; n *= 10) sizes.push_back(n);
  if (sizes.empty() || sizes.back() != maxTriangles) sizes.push_back(maxTriangles);
  return sizes;
}

void benchBvhGrowth(const GrowthOptions& options) {
  std::printf(
      "\nd. BVH growth on generated height-field grids, each measured in a fresh child process.\n"
      "   build: RayTracer construction (Embree BVH + the scene's content hash, also shown alone)\n"
      "   and raw Embree's build; bytes per triangle: Embree's own count, the resident (RSS)\n"
      "   growth for the scene arrays and for the BVH, and the peak; primary rays: %dx%d camera\n"
      "   rays through RayTracer::intersect and raw rtcIntersect1, all cores, best of %d\n",
      options.width, options.width, options.repeats);
  std::printf("%11s %8s %8s %8s | %8s %8s %8s %8s | %8s %8s\n", "", "build", "hash", "raw",
              "Embree", "RSS", "RSS", "peak", "", "raw");
  std::printf("%11s %8s %8s %8s | %8s %8s %8s %8s | %8s %8s\n", "triangles", "s", "s", "build s",
              "B/tri", "scene", "BVH", "RSS", "Mrays/s", "Mrays/s");
  std::fflush(stdout);
  const char* keys[] = {"generate_s",
                        "hash_s",
                        "build_s",
                        "raw_build_s",
                        "embree_bvh_bytes_per_triangle",
                        "resident_scene_bytes_per_triangle",
                        "resident_bvh_bytes_per_triangle",
                        "peak_resident_bytes_per_triangle",
                        "mrays_per_s",
                        "raw_mrays_per_s"};
  CsvRows rows = {{"triangles", "grid_cells"}};
  for (const char* key : keys) rows[0].push_back(key);
  std::vector<double> logTriangles, logBuild, log2Triangles, nsPerRay, rawNsPerRay;
  for (uint64_t target : gridSizes(options.maxTriangles)) {
    const int cells = static_cast<int>(std::lround(std::sqrt(target / 2.0)));
    const GridResult r = measureGridInChild(cells, options.width, options.repeats);
    const double triangles = r["triangles"];
    std::printf("%11.0f %8.3f %8.3f %8.3f | %8.1f %8.1f %8.1f %8.1f | %8.2f %8.2f\n", triangles,
                r["build_s"], r["hash_s"], r["raw_build_s"], r["embree_bvh_bytes_per_triangle"],
                r["resident_scene_bytes_per_triangle"], r["resident_bvh_bytes_per_triangle"],
                r["peak_resident_bytes_per_triangle"], r["mrays_per_s"], r["raw_mrays_per_s"]);
    std::fflush(stdout);
    rows.push_back({number(triangles, 12), std::to_string(cells)});
    for (const char* key : keys) rows.back().push_back(number(r[key], 4));
    logTriangles.push_back(std::log(triangles));
    log2Triangles.push_back(std::log2(triangles));
    logBuild.push_back(std::log(r["build_s"]));
    nsPerRay.push_back(1e3 / r["mrays_per_s"]);
    rawNsPerRay.push_back(1e3 / r["raw_mrays_per_s"]);
  }
  if (logTriangles.size() >= 2) {
    std::printf(
        "fits (least squares): build seconds ~ triangles^%.2f; time per primary ray grows by "
        "%.1f ns (raw Embree %.1f ns) per doubling of the triangles\n",
        fittedSlope(logTriangles, logBuild), fittedSlope(log2Triangles, nsPerRay),
        fittedSlope(log2Triangles, rawNsPerRay));
  }
  writeCsv(options.outDir, "bvh.csv", rows);
}

}  // namespace

int growthGridChild(int cells, int width, int repeats) {
  const long before = residentBytes();
  Scene scene;
  const double generateSeconds = secondsOf([&] { scene = gridScene(cells); });
  const long afterScene = residentBytes();
  const double hashSeconds = secondsOf([&] { (void)scene.contentHash(); });
  std::unique_ptr<RayTracer> tracer;
  const double buildSeconds = secondsOf([&] { tracer = std::make_unique<RayTracer>(scene); });
  const long afterBuild = residentBytes();
  const long peak = procKilobytes("/proc/self/status", "VmHWM:");

  const Camera camera(scene, width, width);
  std::vector<Ray> rays;
  Pcg32 rng(1);
  for (int y = 0; y < width; ++y)
    for (int x = 0; x < width; ++x)
      rays.push_back(camera.generateRay(Vec2(x + rng.nextFloat(), y + rng.nextFloat())));
  std::vector<float> sink(rays.size());
  // Raw Embree once the memory figures above are taken: its BVH is a second copy.
  std::unique_ptr<RawEmbree> raw;
  const double rawBuildSeconds = secondsOf([&] { raw = std::make_unique<RawEmbree>(scene); });
  auto traceAll = [&](auto trace) {
    return secondsOf([&] {
      tbb::parallel_for(size_t(0), rays.size(), [&](size_t i) { sink[i] = trace(rays[i]); });
    });
  };
  double seconds = 1e30, rawSeconds = 1e30;
  // In turns, so that on a shared machine both see the same load.
  for (int round = 0; round < repeats; ++round) {
    seconds = std::min(seconds, traceAll([&](const Ray& ray) {
                         RayCounters ignored;
                         const auto hit = tracer->intersect(ray, RayKind::Primary, ignored);
                         return hit ? hit->distance : kInfinity;
                       }));
    rawSeconds =
        std::min(rawSeconds, traceAll([&](const Ray& ray) { return raw->intersect(ray); }));
  }
  const double mrays = rays.size() / seconds * 1e-6, rawMrays = rays.size() / rawSeconds * 1e-6;

  const double triangles = static_cast<double>(scene.triangleCount());
  std::printf(
      "triangles=%.0f generate_s=%.6g hash_s=%.6g build_s=%.6g raw_build_s=%.6g "
      "embree_bvh_bytes_per_triangle=%.6g resident_scene_bytes_per_triangle=%.6g "
      "resident_bvh_bytes_per_triangle=%.6g peak_resident_bytes_per_triangle=%.6g "
      "mrays_per_s=%.6g raw_mrays_per_s=%.6g\n",
      triangles, generateSeconds, hashSeconds, buildSeconds, rawBuildSeconds,
      tracer->bvhBytes() / triangles, (afterScene - before) / triangles,
      (afterBuild - afterScene) / triangles, (peak - before) / triangles, mrays, rawMrays);
  return 0;
}

int benchGrowth(const GrowthOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  if (!options.outDir.empty()) {
    std::error_code error;
    std::filesystem::create_directories(options.outDir, error);
    if (error)
      throw PathwayError(options.outDir + ": cannot create the folder: " + error.message());
  }
  const std::string cpu = cpuModel();
  const int cores = tbb::info::default_concurrency();
  const double memoryGiB = procKilobytes("/proc/meminfo", "MemTotal:") / double(1 << 30);
  // Other processes share the machine: say how busy it was.
  const double load = loadAverage();
  std::printf(
      "pathway_bench growth: %s, %d cores, %.1f GiB, load average %.2f at the start, Embree %s, "
      "%s\n",
      cpu.c_str(), cores, memoryGiB, load, RTC_VERSION_STRING, utcNow().c_str());
  const std::string caches = dataCaches();
  const Scene scene = loadScene(options.scene);
  std::printf("caches: %s; scene for tables a-c: %s (%zu triangles)\n\n", caches.c_str(),
              options.scene.c_str(), scene.triangleCount());
  std::fflush(stdout);
  writeCsv(options.outDir, "machine.csv",
           {{"key", "value"},
            {"cpu", cpu},
            {"cores", std::to_string(cores)},
            {"memory_gib", number(memoryGiB, 3)},
            {"load_average", number(load, 3)},
            {"caches", caches},
            {"embree", RTC_VERSION_STRING},
            {"date", utcNow()},
            {"scene", std::filesystem::path(options.scene).filename().string()},
            {"width", std::to_string(options.width)},
            {"repeats", std::to_string(options.repeats)},
            {"spp_width", std::to_string(kSppSide)}});

  RayTracer tracer(scene);
  benchStagesAndThreads(scene, tracer, options);
  benchSpp(scene, tracer, options);
  benchBvhGrowth(options);
  std::printf("\ntotal %.0f s",
              std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  if (!options.outDir.empty()) std::printf("; CSV files in %s", options.outDir.c_str());
  std::printf("\n");
  return 0;
}

}  // namespace pathway::bench
