// Tests of `pathway chart`: the error measure against its formula, the configuration syntax and
// its refusals, the statistics (medians, log-log fits, read-offs) on exact power laws, the cache,
// and on real renders the convergence rate plain Monte Carlo must show.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "chart/chart_summary.h"
#include "chart/filter_profiles.h"
#include "core/error.h"
#include "render/integrator_registry.h"
#include "run_command.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kBox = std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf";

TEST(ImageError, MatchesTheFormula) {
  Image reference(2, 1), image(2, 1);
  reference.at(0, 0) = Color(1.0f, 0.0f, 0.5f);
  reference.at(1, 0) = Color(0.0f);
  image.at(0, 0) = Color(1.5f, 0.1f, 0.5f);
  image.at(1, 0) = Color(0.2f, 0.0f, 0.0f);
  const ImageError error = imageError(image, reference);
  // Six channel values: squared differences 0.25, 0.01, 0, 0.04, 0, 0.
  const double eps = kRelMseEpsilon;
  const double relMse = (0.25 / (1.0 + eps) + 0.01 / eps + 0.04 / eps) / 6.0;
  EXPECT_NEAR(error.relMse, relMse, 1e-6);
  EXPECT_NEAR(error.mse, 0.3 / 6.0, 1e-7);
  EXPECT_NEAR(error.rmse(), std::sqrt(0.05), 1e-7);
  EXPECT_EQ(imageError(reference, reference).relMse, 0.0);
  EXPECT_THROW(imageError(Image(3, 1), reference), PathwayError);
  EXPECT_THROW(imageError(Image(), Image()), PathwayError);
}

TEST(ChartConfig, ReadsLabelIntegratorKeysAndParameters) {
  const ChartConfig config = parseChartConfig(
      "nested 1:3, Sobol': stage2@ref ao-rays=3 sampler=sobol filter=tent filter-radius=1.5 "
      "max-spp=64 reference=\"4D, Sobol'\" group=\"nested AO\" x=0.25 scene=a.gltf");
  EXPECT_EQ(config.label, "nested 1:3, Sobol'");
  EXPECT_EQ(config.choices.integrator, "stage2@ref");
  EXPECT_EQ(config.choices.params, std::vector<std::string>{"ao-rays=3"});
  EXPECT_EQ(config.choices.sampler, "sobol");
  EXPECT_EQ(config.choices.filter, "tent");
  EXPECT_FLOAT_EQ(config.choices.filterRadius, 1.5f);
  EXPECT_EQ(config.maxSpp, 64u);
  EXPECT_EQ(config.referenceFrom, "4D, Sobol'");
  EXPECT_EQ(config.group, "nested AO");
  ASSERT_TRUE(config.x.has_value());
  EXPECT_DOUBLE_EQ(*config.x, 0.25);
  EXPECT_EQ(config.choices.scene, "a.gltf");
}

TEST(ChartConfig, RefusesMalformedText) {
  for (const char* text :
       {"no separator", ": stage1@ref", "label: ", "a: stage1 x=wide", "a: stage1 max-spp=3",
        "a: stage1 max-spp=0", "a: stage1 loose", "a: stage1 group=\"open"}) {
    EXPECT_THROW(parseChartConfig(text), PathwayError) << text;
  }
}

ChartSpec specOf(const std::vector<std::string>& configs) {
  ChartSpec spec;
  spec.scene = kBox;
  for (const std::string& text : configs) spec.configs.push_back(parseChartConfig(text));
  return spec;
}

// The check names the configuration and the problem.
void expectRefused(const ChartSpec& spec, const std::string& needle) {
  try {
    spec.check();
    ADD_FAILURE() << "accepted; expected a message naming " << needle;
  } catch (const PathwayError& error) {
    EXPECT_NE(std::string(error.what()).find(needle), std::string::npos) << error.what();
  }
}

TEST(ChartSpec, RefusesWhatCannotBeCharted) {
  expectRefused(specOf({"a: nosuchstage"}), "nosuchstage");
  expectRefused(specOf({"a: stage2 ao-rays=0"}), "ao-rays");
  expectRefused(specOf({"a: stage1 sampler=halton"}), "halton");
  // Settings out of their declared range, refused before anything renders.
  expectRefused(specOf({"a: stage1 filter=tent filter-radius=9"}), "filter-radius must be in");
  expectRefused(specOf({"a: stage1", "a: stage1 filter=tent"}), "two chart configurations");
  expectRefused(specOf({"a: stage1 reference=b"}), "reference=b");
  // A reference must estimate the same image: same scene, same filter.
  expectRefused(specOf({"a: stage1 filter=tent", "b: stage1 reference=a"}), "another filter");
  expectRefused(specOf({"a: stage1 scene=x.gltf", "b: stage1 reference=a"}), "another scene");
  // ... and the same parameters where they change the image: AO length yes, AO ray count no.
  expectRefused(specOf({"a: stage3 ao-distance=0.5", "b: stage2 ao-rays=8 reference=a"}),
                "ao-distance=0.5 (not 0.25)");
  EXPECT_NO_THROW(specOf({"a: stage3", "b: stage2 ao-rays=8 reference=a"}).check());
  EXPECT_NO_THROW(specOf({"a: stage5", "b: stage5 nee=off light-pick=area reference=a"}).check());
  ChartSpec spec = specOf({"a: stage1"});
  spec.maxSpp = 48;
  expectRefused(spec, "power of two");
  spec = specOf({});
  expectRefused(spec, "at least one");
}

TEST(ChartSummary, MediansFitsAndReadOffsOnAnExactPowerLaw) {
  // relMSE = 0.5 / spp, seconds = 0.01 spp: slope -1 in both, 1e-3 reached at spp 500 (5 s).
  ChartSpec spec = specOf({"a: stage1"});
  spec.maxSpp = 64;
  spec.seeds = 3;
  ChartData data;
  data.descriptions = {"a"};
  for (uint32_t spp = 1; spp <= 64; spp *= 2) {
    for (uint64_t seed = 1; seed <= 3; ++seed) {
      ChartRun run;
      run.label = "a";
      run.seed = seed;
      run.spp = spp;
      // The seeds scatter around the law; the median is the middle one.
      const double scatter = seed == 1 ? 0.5 : seed == 2 ? 1.0 : 3.0;
      run.seconds = 0.01 * spp;
      run.error = ImageError{0.5 / spp * scatter, 0.25 / spp * scatter};
      run.counters.primary = run.counters.samples = 100ull * spp;
      data.runs.push_back(run);
    }
  }
  const ChartSummary summary = summarizeChart(spec, data);
  ASSERT_EQ(summary.lines.size(), 1u);
  const ChartLine& line = summary.lines[0];
  ASSERT_EQ(line.points.size(), 7u);
  EXPECT_DOUBLE_EQ(*line.points[2].relMse, 0.5 / 4);
  EXPECT_DOUBLE_EQ(*line.points[2].relMseLow, 0.25 / 4);
  EXPECT_DOUBLE_EQ(*line.points[2].relMseHigh, 1.5 / 4);
  EXPECT_NEAR(*line.points[2].efficiency, 1.0 / (0.5 / 4 * 0.04), 1e-9);
  EXPECT_DOUBLE_EQ(line.raysPerSample, 1.0);
  ASSERT_TRUE(line.relMseBySpp && line.relMseBySeconds);
  EXPECT_NEAR(line.relMseBySpp->slope, -1.0, 1e-9);
  EXPECT_NEAR(line.relMseBySeconds->slope, -1.0, 1e-9);
  EXPECT_EQ(line.relMseBySpp->fromSpp, 8u);  // the upper half of exponents 0..6
  ASSERT_TRUE(line.secondsToTarget);
  EXPECT_TRUE(line.secondsToTarget->extrapolated);
  EXPECT_NEAR(line.secondsToTarget->value, 5.0, 1e-6);
  // One line: equal time is its own longest time, read off its last point.
  EXPECT_NEAR(summary.equalSeconds, 0.64, 1e-12);
  EXPECT_NEAR(summary.relMseAtEqualSeconds[0].value, 0.5 / 64, 1e-12);
  EXPECT_FALSE(summary.relMseAtEqualSeconds[0].extrapolated);
  EXPECT_NEAR(summary.rmseAtEqualSeconds[0].value, std::sqrt(0.25 / 64), 1e-12);
}

TEST(ChartRuns, CsvLinesReadBackExactly) {
  ChartRun run;
  run.label = "4D, \"Sobol'\"";
  run.seed = 3;
  run.spp = 16;
  run.seconds = 0.125;
  run.counters.primary = 1, run.counters.secondary = 2, run.counters.shadow = 3;
  run.counters.samples = 4, run.counters.invalidSamples = 5;
  run.error = ImageError{0.25, 0.5};
  run.key = "0123456789abcdef";
  const auto back = parseRunCsvLine(formatRunCsvLine(run));
  ASSERT_TRUE(back);
  EXPECT_EQ(back->label, run.label);
  EXPECT_EQ(back->spp, 16u);
  EXPECT_EQ(back->counters.totalRays(), 6u);
  EXPECT_EQ(back->counters.invalidSamples, 5u);
  EXPECT_DOUBLE_EQ(back->error->mse, 0.5);
  run.error.reset();
  EXPECT_FALSE(parseRunCsvLine(formatRunCsvLine(run))->error);
  EXPECT_FALSE(parseRunCsvLine("cut off,3,16"));
}

class ChartRender : public ::testing::Test {
 protected:
  void SetUp() override { folder_ = test::freshTestFolder("pathway_chart"); }
  void TearDown() override { fs::remove_all(folder_); }
  ChartRunOptions options(int* rendered) const {
    ChartRunOptions o;
    o.folder = folder_.string();
    o.progress = [rendered](double, const std::string&) { ++*rendered; };
    return o;
  }
  fs::path folder_;
};

// Test integrators with a known expected image: one uniform number per sample (mean 1/2), and
// the same 20 % too bright, a bias no number of samples removes.
class UniformIntegrator : public Integrator {
 public:
  explicit UniformIntegrator(float gain) : gain_(gain) {}
  Color Li(const Ray&, SampleStream& samples, const RenderContext&) const override {
    return Color(gain_ * samples.next1D());
  }

 private:
  float gain_;
};

IntegratorInfo uniformIntegrator(const std::string& name, float gain) {
  return {name,
          0,
          Variant::Reference,
          "chart test: a uniform random number",
          {},
          SamplerType::Independent,
          [gain](const IntegratorSetup&) { return std::make_unique<UniformIntegrator>(gain); }};
}
const bool kRegistered = registerIntegrator(uniformIntegrator("chart-test-uniform", 1.0f)) &&
                         registerIntegrator(uniformIntegrator("chart-test-brighter", 1.2f));

// Plain Monte Carlo converges as 1/spp, in a real stage and in the test integrator; against a
// reference of another image the error levels off at the bias (this is how the check fails).
// With 4 seeds at 24x18 pixels the fitted slopes are deterministic; the bounds leave ±0.15 for
// scatter.
TEST_F(ChartRender, IndependentSamplingConvergesAtSlopeMinusOne) {
  PATHWAY_REQUIRE_REFERENCE();
  ASSERT_TRUE(kRegistered);
  ChartSpec spec =
      specOf({"stage 3: " + test::stage(3) + " sampler=independent", "uniform: chart-test-uniform",
              "biased: chart-test-brighter reference=uniform"});
  spec.width = 24;
  spec.maxSpp = 64;
  spec.seeds = 4;
  int rendered = 0;
  const ChartData data = runChart(spec, options(&rendered));
  EXPECT_GT(rendered, 0);
  EXPECT_EQ(data.runs.size(), 3u * 7 * 4);
  const ChartSummary summary = summarizeChart(spec, data);
  for (const ChartLine& line : summary.lines) ASSERT_TRUE(line.relMseBySpp);
  EXPECT_NEAR(summary.lines[0].relMseBySpp->slope, -1.0, 0.15);
  EXPECT_NEAR(summary.lines[1].relMseBySpp->slope, -1.0, 0.15);
  EXPECT_GT(summary.lines[2].relMseBySpp->slope, -0.5);
  EXPECT_NEAR(summary.lines[0].raysPerSample, 1.9, 0.1);  // a camera ray, and an AO ray on a hit
  EXPECT_TRUE(fs::exists(data.references[0].exrPath));
  EXPECT_EQ(data.references[0].spp, 64u * 64);
  EXPECT_EQ(data.references[1].exrPath, data.references[2].exrPath);

  // A rerun renders nothing and reads the same numbers back.
  int rerendered = 0;
  const ChartData again = runChart(spec, options(&rerendered));
  EXPECT_EQ(rerendered, 0);
  ASSERT_EQ(again.runs.size(), data.runs.size());
  for (size_t i = 0; i < data.runs.size(); ++i) {
    EXPECT_EQ(again.runs[i].key, data.runs[i].key);
    EXPECT_NEAR(again.runs[i].seconds, data.runs[i].seconds, 1e-8 * data.runs[i].seconds);
    EXPECT_NEAR(again.runs[i].error->relMse, data.runs[i].error->relMse,
                1e-8 * data.runs[i].error->relMse);
  }
  // A changed setting renders only what it changes.
  spec.seeds = 5;
  int extra = 0;
  const ChartData more = runChart(spec, options(&extra));
  EXPECT_GT(extra, 0);
  EXPECT_EQ(more.runs.size(), 3u * 7 * 5);
}

TEST(FilterProfiles, TabulateTheCodesFilters) {
  PATHWAY_REQUIRE_REFERENCE();
  Variant used = Variant::Student;
  const std::string csv = filterProfilesCsv(&used);
  EXPECT_EQ(csv.substr(0, csv.find('\n')), "x,box,tent,mitchell,gaussian");
  // Mitchell-Netravali (B = C = 1/3) at x = 0: (6 - 2B)/6 = 8/9.
  const size_t zero = csv.find("\n0.0000,");
  ASSERT_NE(zero, std::string::npos);
  const std::string row = csv.substr(zero + 1, csv.find('\n', zero + 1) - zero - 1);
  EXPECT_EQ(row.substr(0, 14), "0.0000,1,1,0.8");
  EXPECT_NEAR(std::stod(row.substr(row.find(",0.8") + 1)), 8.0 / 9.0, 1e-6);
}

// The chart command end to end: bad input is refused with a message naming it, before anything
// renders; the ready-made chart sets run (at --quick size) and draw every figure.
TEST(ChartCommand, RefusesBadConfigurations) {
  const std::string pathway = PATHWAY_BINARY;
  const fs::path folder = fs::temp_directory_path() / "pathway_chart_refused";
  fs::remove_all(folder);
  for (const auto& [arguments, needle] : std::vector<std::pair<std::string, std::string>>{
           {"-c 'a: stage9'", "stage9"},
           {"-c 'a stage1'", "LABEL: INTEGRATOR"},
           {"--max-spp 48 -c 'a: stage1'", "power of two"},
           {"/nowhere.gltf -c 'a: stage1'", "nowhere.gltf"},
           {"", "at least one"}}) {
    const test::CommandOutcome outcome =
        test::runCommand(pathway + " chart " + arguments + " -q -o " + folder.string());
    EXPECT_NE(outcome.exitCode, 0) << arguments;
    EXPECT_NE(outcome.output.find(needle), std::string::npos) << arguments << "\n"
                                                              << outcome.output;
  }
  EXPECT_FALSE(fs::exists(folder / "runs.csv"));
  fs::remove_all(folder);
}

TEST(ChartCommand, ReadyMadeSetsRunAndDraw) {
  PATHWAY_REQUIRE_REFERENCE();
  if (!fs::exists(PATHWAY_SOURCE_DIR "/scripts/charts"))
    GTEST_SKIP() << "the lecture's chart sets (scripts/charts) are not in a handout";
  const fs::path folder = fs::temp_directory_path() / "pathway_chart_sets";
  fs::remove_all(folder);
  const test::CommandOutcome outcome = test::runCommand(
      std::string(PATHWAY_SOURCE_DIR) +
      "/scripts/charts all --quick --program " PATHWAY_BINARY " --out " + folder.string());
  ASSERT_EQ(outcome.exitCode, 0) << outcome.output;
  for (const char* figure :
       {"ao-splits/chart.png", "ao-splits/bars.svg", "samplers/stage1/chart.png",
        "samplers/stage3/bars.png", "recursion/chart.png", "recursion/rays/rays.png",
        "nee/sweep.png", "nee/chart.svg", "filters/filters.png", "filters/chart.png"})
    EXPECT_GT(fs::exists(folder / figure) ? fs::file_size(folder / figure) : 0, 1000u) << figure;
  const std::string measured =
      test::readTextFile((folder / "samplers/stage3/measured.txt").string());
  EXPECT_NE(measured.find("RMSE at 8 spp"), std::string::npos) << measured;
  fs::remove_all(folder);
}

}  // namespace
}  // namespace pathway
