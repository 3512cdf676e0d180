#include "grade/stage_grading.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>

#include "core/child_process.h"
#include "core/error.h"
#include "core/temporary_folder.h"
#include "render/stage_library.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// "file:line; file:line" (render metadata) -> the sites.
std::vector<std::string> todoSites(const std::map<std::string, std::string>& metadata) {
  std::vector<std::string> sites;
  const auto it = metadata.find("pathway:todoSites");
  if (it == metadata.end()) return sites;
  const std::string& text = it->second;
  for (size_t start = 0; start < text.size();) {
    size_t end = text.find("; ", start);
    if (end == std::string::npos) end = text.size();
    sites.push_back(text.substr(start, end - start));
    start = end + 2;
  }
  return sites;
}

CaseResult gradeCase(const GradingCase& gradingCase, const GradingRun& run,
                     const std::string& workFolder, const ComparisonSettings& settings) {
  CaseResult result;
  result.id = gradingCase.id();
  result.title = "Stage " + std::to_string(gradingCase.stage) + " · " + gradingCase.name;
  result.purpose = gradingCase.purpose;
  result.stage = gradingCase.stage;
  try {
    const GradingReference reference =
        readGradingReference(run.references + "/" + gradingCase.referenceFile());
    // Long enough for a correct stage on a slow machine, short enough that a stage stuck in a
    // loop cannot run a whole class (or Gradescope's time limit) out.
    const double limit = std::min(
        run.timeLimit, std::max(kMinimumCaseSeconds, kCaseTimeFactor * reference.secondsPerRender));
    // Renders the case with `seed`; nullopt (and the reason in `result`) when the stage failed.
    auto render = [&](uint64_t seed) -> std::optional<LoadedImage> {
      GradingRun once = run;
      once.seed = seed;
      const std::string output = workFolder + "/" + result.id + "-" + std::to_string(seed);
      const ChildOutcome child =
          runChild(renderCaseArguments(gradingCase, once, output + ".exr"), limit, output + ".log");
      if (child.succeeded()) return readImageFile(output + ".exr");
      result.crashed = child.signal != 0;
      result.timedOut = child.timedOut;
      result.problem = "your stage " + child.describe(limit) + " while rendering " +
                       gradingCase.scene + ":\n" + child.output;
      return std::nullopt;
    };
    const std::optional<LoadedImage> first = render(run.seed);
    if (!first) return result;
    judgeAgainstReference(result, *first, reference, settings);
    const bool statistical = result.compared && result.comparison.hardFailures.empty() &&
                             result.todos.empty() && result.problem.empty();
    if (!result.passed && statistical) {
      // A correct stage fails a case by chance about once in a thousand renders; a wrong one
      // fails again. So a failure counts only when a render with another seed fails too.
      const uint64_t seed = run.seed + kConfirmationSeedOffset;
      CaseResult second = result;
      const std::optional<LoadedImage> again = render(seed);
      if (!again) return result;
      judgeAgainstReference(second, *again, reference, settings);
      result.passed = second.passed;
      result.note = second.passed
                        ? "the first render failed, but a second with seed " +
                              std::to_string(seed) + " passed: a chance failure, not counted"
                        : "a second render with seed " + std::to_string(seed) + " failed too";
    }
  } catch (const std::exception& error) {
    result.problem = error.what();
  }
  return result;
}

}  // namespace

std::vector<std::string> renderCaseArguments(const GradingCase& gradingCase, const GradingRun& run,
                                             const std::string& output) {
  // `pathway grade` reads these (framework/app/grade_command.cpp).
  std::vector<std::string> arguments = {
      currentExecutable(), "grade", "--render-case", gradingCase.id(),
      "--render-output",   output,  "--seed",        std::to_string(run.seed)};
  if (run.together) arguments.push_back("--together");
  if (run.gradeReference) arguments.push_back("--grade-reference");
  for (const std::string& library : run.stageLibraries) {
    arguments.push_back("--stages-library");
    arguments.push_back(fs::absolute(library).string());
  }
  return arguments;
}

void renderGradingCase(const GradingCase& gradingCase, const GradingRun& run,
                       const std::string& output) {
  limitThisChild(64ull << 20);  // a render and its log need far less than 64 MiB
  bool registered = run.stageLibraries.empty();
  for (const std::string& library : run.stageLibraries)
    for (int stage : loadStageLibrary(library)) registered |= stage == gradingCase.stage;
  if (!registered)
    throw PathwayError("no stage library given registers stage " +
                       std::to_string(gradingCase.stage) +
                       " (does its file end with its registerStage line?)");
  const RenderRecipe recipe =
      gradingCase.recipe(run.gradeReference ? Variant::Reference : Variant::Student,
                         run.together ? EarlierStages::Own : EarlierStages::Reference, run.seed);
  const Scene scene = loadScene(run.scenes + "/" + gradingCase.scene);
  const RayTracer tracer(scene);
  const RenderResult result = runRender(tracer, recipe);
  writeExr(output, result.images, result.metadata);
}

void judgeAgainstReference(CaseResult& result, const LoadedImage& render,
                           const GradingReference& reference, const ComparisonSettings& settings) {
  result.todos = todoSites(render.metadata);
  result.seconds = metadataNumber(render.metadata, "pathway:seconds");
  result.raysPerSecond = metadataNumber(render.metadata, "pathway:raysPerSecond");
  result.referenceSeconds = reference.secondsPerRender;
  result.referenceRaysPerSecond = reference.raysPerSecond;
  result.comparison = compareWithReference(render.images, render.metadata, reference, settings);
  result.compared = true;
  result.passed = result.comparison.passed(settings);
  result.image = render.images.color;
  result.reference = reference.mean;
  if (!result.todos.empty()) {
    // A placeholder can be right by chance (the box filter's is); unfinished work never passes.
    result.passed = false;
    result.problem = "your stage is unfinished: its TODOs ran (listed below)";
  }
}

double casePoints(int index, int count) {
  const double share = std::round(100.0 * kPointsPerStage / count) / 100.0;
  return index + 1 < count ? share : kPointsPerStage - share * (count - 1);
}

GradeSummary gradeStages(const GradingRun& run, const ComparisonSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  GradeSummary summary;
  summary.title = std::string("Pathway grading: ") +
                  (run.gradeReference ? "the reference stages themselves"
                   : run.together     ? "your stages together"
                                      : "each stage on the reference's earlier stages");
  const TemporaryFolder work("pathway-grade");  // the renders and their logs; removed at the end
  std::map<int, int> casesPerStage, done;
  for (const GradingCase* c : run.cases) ++casesPerStage[c->stage];
  for (const GradingCase* c : run.cases) {
    if (run.progress) std::fprintf(stderr, "grading %s ...\n", c->id().c_str());
    CaseResult result = gradeCase(*c, run, work.path(), settings);
    result.maxPoints = casePoints(done[c->stage]++, casesPerStage[c->stage]);
    result.points = result.passed ? result.maxPoints : 0.0;
    summary.cases.push_back(std::move(result));
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

}  // namespace pathway
