#include "grade/stage_grading.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

#include "core/child_process.h"
#include "core/error.h"
#include "core/number_format.h"
#include "core/regular_file_copy.h"
#include "core/temporary_folder.h"
#include "engine/pixel_in_progress.h"
#include "grade/case_render_job.h"
#include "grade/reference_comparison.h"
#include "grade/stage_warp_test.h"
#include "render/parameters.h"
#include "stage_loading/reference_library.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

// How a case's render went: its image, or why there is none.
struct RenderOutcome {
  std::optional<LoadedImage> image;
  bool crashed = false;
  bool timedOut = false;
  std::string problem;
};

// How much of a stopped child's output a message quotes: its last lines.
constexpr int kQuotedOutputLines = 12;

// "your stage crashed (signal 4, Illegal instruction) in case stage2-ceiling (ceiling.gltf, 64x64,
// 8 spp) while rendering pixel (12, 40); its last output: ..."
std::string stopMessage(const ChildOutcome& child, const GradingCase& gradingCase, double limit) {
  const bool sandboxed = !child.succeeded() && child.signal == SIGSYS;
  const std::string how = child.succeeded() ? "stopped without writing its image"
                          : sandboxed       ? "was stopped by the grader's sandbox"
                                            : child.describe(limit);
  std::string message = "your stage " + how + " in case " + gradingCase.id() + " (" +
                        gradingCase.scene + ", " + std::to_string(gradingCase.width) + "x" +
                        std::to_string(gradingCase.height) + ", " +
                        std::to_string(gradingCase.spp) + " spp)";
  const std::string pixels = pixelsInProgressFrom(child.output);
  if (!pixels.empty())
    message += (pixels.find("), (") != std::string::npos ? " while rendering pixels "
                                                         : " while rendering pixel ") +
               pixels;
  if (sandboxed)
    message +=
        ": it tried to open a network connection, start a process or reach into another "
        "process (signal 31, a forbidden system call), which no stage does";
  // The child's own lines, without the ones that named the pixel and the sandbox.
  std::vector<std::string> lines;
  std::istringstream in(child.output);
  for (std::string line; std::getline(in, line);)
    if (!line.empty() && line.rfind("pathway: stopped by ", 0) != 0 &&
        line.rfind("pathway: sandbox ", 0) != 0)
      lines.push_back(line);
  if (lines.empty()) return message + "; it printed nothing before it stopped";
  message += "; its last output:";
  const size_t first = lines.size() > kQuotedOutputLines ? lines.size() - kQuotedOutputLines : 0;
  for (size_t i = first; i < lines.size(); ++i) message += "\n  " + lines[i];
  return message;
}

// The parent's own limit on a child, on top of its cases' limits: the child's alarms end it
// first; this only catches a stage that blocks SIGALRM.
constexpr double kChildGraceSeconds = 10.0;
// What one child may write in its folder, all files together: its cases' images take a few MiB
// each. Past it the child is stopped (its case fails, saying so), so no stage can fill the disk.
constexpr uint64_t kChildFolderQuotaBytes = 256ull << 20;
// The most channels a case's image has (colour, variance, weight, its batches' jackknife layers),
// with room to spare: an image that declares more is not read.
constexpr size_t kCaseImageChannels = 256;

// A child's job for `stage` of `run` with `seed`, before its cases, warp test and folder: where
// its earlier stages come from, its libraries, its sandbox.
CaseRenderJob childJob(const GradingRun& run, int stage, uint64_t seed) {
  CaseRenderJob job;
  job.scenes = run.scenes;
  job.seed = seed;
  job.together = run.together;
  job.gradeReference = run.gradeReference;
  job.singleRay = run.tracing == ReferenceTracing::SingleRay;
  job.sandbox = run.sandbox;
  job.referenceStages = CaseRenderJob::referenceStagesFor(stage, run.gradeReference, run.together);
  if (!job.referenceStages.empty()) job.referenceFolder = referenceLibraryFolder();
  job.reportsSandbox = true;
  for (const std::string& library : run.stageLibraries)
    job.stageLibraries.push_back(fs::absolute(library).string());
  return job;
}

// How a child of `run` is started: untrusted, its sandbox's report read, its folder's size capped.
ChildOptions childOptions(const GradingRun& run) {
  ChildOptions options = untrustedChildOptions(run.sandbox != SandboxMode::Off);
  options.reportChannel = true;
  if (run.sandbox != SandboxMode::Off) options.folderQuotaBytes = kChildFolderQuotaBytes;
  return options;
}

// Renders `cases` (each within its limit, all of one stage) with `seed` in as few child processes
// as crashes and hangs allow: one child renders them all in order; when it stops early, the case it
// was on fails and the cases after it go to a new child. Each child gets a folder of its own under
// `workFolder`, removed once its images are read; `sandboxSeen` collects what each child said its
// sandbox held.
std::vector<RenderOutcome> renderInChildren(const std::vector<CaseRenderJob::Case>& cases,
                                            const GradingRun& run, uint64_t seed,
                                            const std::string& workFolder,
                                            std::vector<std::string>* sandboxSeen = nullptr) {
  std::vector<RenderOutcome> outcomes(cases.size());
  if (cases.empty()) return outcomes;
  CaseRenderJob job = childJob(run, cases.front().gradingCase->stage, seed);
  ChildOptions options = childOptions(run);
  for (size_t next = 0; next < cases.size();) {
    job.cases.assign(cases.begin() + next, cases.end());
    double total = kChildGraceSeconds;
    for (const CaseRenderJob::Case& c : job.cases) total += c.timeLimit;
    const std::string name = cases[next].gradingCase->id() + "-" + std::to_string(seed);
    const std::string log = workFolder + "/" + name + ".log";
    job.output = workFolder + "/" + name;
    fs::remove_all(job.output);
    fs::create_directory(job.output);
    // A child of a root grader runs as nobody: the folder it writes its renders in is its own.
    shareWithSandboxUser(job.output, run.sandbox);
    options.watchedFolder = job.output;
    std::vector<std::string> command = {PATHWAY_CHILD_PROGRAM};
    for (const std::string& argument : job.toArguments()) command.push_back(argument);
    ChildOutcome child = runChild(command, total, log, options);
    if (sandboxSeen && !child.report.empty()) sandboxSeen->push_back(child.report);
    // Images are written whole or not at all (image_io.h): each one there is a finished case.
    const size_t first = next;
    for (; next < cases.size(); ++next) {
      const GradingCase& gradingCase = *cases[next].gradingCase;
      const std::string image = job.imagePath(gradingCase);
      std::error_code missing;
      const fs::file_status status = fs::symlink_status(image, missing);
      if (missing || !fs::exists(status)) break;
      try {
        // The child has ended (and all it started): nothing changes the folder any more.
        if (!fs::is_regular_file(status))
          throw PathwayError(image + ": not a regular file (a link, a pipe?): not read");
        // Written by student code: read only if it is the case's size.
        outcomes[next].image = readImageFile(
            image, RasterLimits{gradingCase.width, gradingCase.height, kCaseImageChannels});
      } catch (const std::exception& error) {
        outcomes[next].problem = error.what();
      }
    }
    std::error_code ignored;
    fs::remove_all(job.output, ignored);
    // A stage starts no process and writes nothing but its images; one that did (where the
    // sandbox could not refuse it) fails every case its child rendered, whatever the images.
    if (child.leftBehind > 0 || child.overQuota)
      for (size_t i = first; i < next; ++i) {
        outcomes[i].image.reset();
        outcomes[i].problem =
            child.overQuota
                ? "your stage " + child.describe(0.0) + "; a stage writes nothing but its image"
                : "your stage started " + std::to_string(child.leftBehind) +
                      " process(es) that outlived its render (the grader ended them); "
                      "a stage starts none";
      }
    if (next == cases.size()) break;
    // The child stopped on cases[next].
    if (child.signal == SIGALRM) {  // its own alarm: that case's time limit
      child.signal = 0;
      child.timedOut = true;
    }
    RenderOutcome& failed = outcomes[next];
    failed.crashed = child.signal != 0;
    failed.timedOut = child.timedOut;
    failed.problem = stopMessage(child, *cases[next].gradingCase, cases[next].timeLimit);
    ++next;
  }
  return outcomes;
}

// The most a warp test's outcome may hold: a few lines of verdict.
constexpr uintmax_t kWarpTestOutcomeBytes = 64 << 10;

// The warp test of `stage`'s sampling routine (grade/stage_warp_test.h), run in a child of its own
// as the cases are, as a check beside them: it carries no points, since the child that writes
// its outcome runs the student's code (a stage could write "passed" itself).
CaseResult warpTestInChild(int stage, const GradingRun& run, const std::string& workFolder,
                           std::vector<std::string>* sandboxSeen) {
  CaseResult result;
  result.id = "stage" + std::to_string(stage) + "-warptest";
  result.title = "Stage " + std::to_string(stage) + " · warp test (no points)";
  result.purpose = stage == 2 ? "your sampleCosineHemisphere against your cosineHemispherePdf"
                              : "your sampleLight's points against their pdfArea";
  result.stage = stage;
  CaseRenderJob job = childJob(run, stage, run.seed);
  job.warpTestStage = stage;
  job.output = workFolder + "/" + result.id;
  const std::string log = job.output + ".log";
  fs::remove_all(job.output);
  fs::create_directory(job.output);
  shareWithSandboxUser(job.output, run.sandbox);
  ChildOptions options = childOptions(run);
  options.watchedFolder = job.output;
  std::vector<std::string> command = {PATHWAY_CHILD_PROGRAM};
  for (const std::string& argument : job.toArguments()) command.push_back(argument);
  const ChildOutcome child =
      runChild(command, CaseRenderJob::kWarpTestSeconds + kChildGraceSeconds, log, options);
  if (sandboxSeen && !child.report.empty()) sandboxSeen->push_back(child.report);
  const std::string path = job.warpTestPath();
  std::error_code missing;
  const fs::file_status status = fs::symlink_status(path, missing);
  if (!missing && fs::is_regular_file(status) &&
      fs::file_size(path, missing) <= kWarpTestOutcomeBytes && !missing) {
    std::ifstream in(path, std::ios::binary);
    std::string first, line, verdict;
    std::getline(in, first);
    while (std::getline(in, line)) verdict += (verdict.empty() ? "" : "\n") + line;
    result.passed = first == "passed";
    result.note = verdict;
  }
  if (result.note.empty()) {
    result.passed = false;
    // The child's own last line says why (a stage that is not there, a crash, a hang).
    std::string said;
    std::istringstream in(child.output);
    for (std::string line; std::getline(in, line);)
      if (!line.empty() && line.rfind("pathway: ", 0) != 0) said = line;
    result.crashed = child.signal != 0 && child.signal != SIGALRM;
    result.timedOut = child.timedOut || child.signal == SIGALRM;
    result.problem =
        "the warp test could not finish: your stage " +
        (result.timedOut ? std::string("ran past its ") +
                               formatNumber("%.0f", CaseRenderJob::kWarpTestSeconds) + " s"
                         : child.describe(CaseRenderJob::kWarpTestSeconds)) +
        (said.empty() ? "" : "; its last output: " + said);
  }
  std::error_code ignored;
  fs::remove_all(job.output, ignored);
  return result;
}

// Long enough for a correct stage on a slow machine, short enough that a stage stuck in a loop
// cannot run a whole class (or Gradescope's time limit) out.
double caseLimit(const GradingRun& run, const GradingReference& reference) {
  return std::min(run.timeLimit, std::max(kMinimumCaseSeconds,
                                          kCaseTimeFactor * reference.record.secondsPerRender));
}

CaseResult caseHeader(const GradingCase& gradingCase) {
  CaseResult result;
  result.id = gradingCase.id();
  result.title = "Stage " + std::to_string(gradingCase.stage) + " · " + gradingCase.name;
  result.purpose = gradingCase.purpose;
  result.stage = gradingCase.stage;
  return result;
}

void takeProblem(CaseResult& result, const RenderOutcome& outcome) {
  result.crashed = outcome.crashed;
  result.timedOut = outcome.timedOut;
  result.problem = outcome.problem;
}

// Judges a case from its first render; a statistical failure is confirmed with a second seed.
void gradeCase(CaseResult& result, const GradingCase& gradingCase, const GradingRun& run,
               const GradingReference& reference, double limit, const RenderOutcome& first,
               const std::string& workFolder, const ComparisonSettings& settings) {
  try {
    if (!first.image) return takeProblem(result, first);
    judgeAgainstReference(result, *first.image, reference, settings);
    const bool statistical = result.compared && result.comparison.hardFailures.empty() &&
                             result.todos.empty() && result.problem.empty();
    if (!result.passed && statistical) {
      // A correct stage fails a case by chance about once in a thousand renders; a wrong one
      // fails again. So a failure counts only when a render with another seed fails too.
      const uint64_t seed = run.seed + kConfirmationSeedOffset;
      const RenderOutcome again =
          renderInChildren({{&gradingCase, limit}}, run, seed, workFolder).front();
      if (!again.image) return takeProblem(result, again);
      CaseResult second = result;
      judgeAgainstReference(second, *again.image, reference, settings);
      result.passed = second.passed;
      if (second.passed) result.diagnosis.reset();  // a chance failure has no cause
      result.note = second.passed
                        ? "the first render failed, but a second with seed " +
                              std::to_string(seed) + " passed: a chance failure, not counted"
                        : "a second render with seed " + std::to_string(seed) + " failed too";
    }
  } catch (const std::exception& error) {
    result.problem = error.what();
  }
}

}  // namespace

void judgeAgainstReference(CaseResult& result, const LoadedImage& render,
                           const GradingReference& reference, const ComparisonSettings& settings) {
  result.todos = render.metadata.todoSites;
  if (const auto& timing = render.metadata.timing) {
    result.seconds = timing->seconds;
    result.raysPerSecond = timing->raysPerSecond;
  }
  result.referenceSeconds = reference.record.secondsPerRender;
  result.referenceRaysPerSecond = reference.record.raysPerSecond;
  result.comparison = compareWithReference(render.images, render.metadata, reference, settings);
  result.compared = true;
  result.passed = result.comparison.passed(settings);
  result.image = render.images.color;
  result.reference = reference.mean;
  result.diagnosis.reset();
  // A copy of the reference has no cause to diagnose: its message says what it is.
  if (!result.passed && result.todos.empty() && !result.comparison.tooClose(settings)) {
    DiagnosisInput input;
    input.image = &result.image;
    input.reference = &reference.mean;
    input.tileVariance = &reference.tileVariance;
    if (!render.images.variance.pixels.empty()) input.imageVariance = &render.images.variance;
    input.replicates = reference.record.replicates;
    input.tileSize = reference.record.tileSize;
    input.stage = result.stage;
    input.nextEventEstimation =
        usedNextEventEstimation(render.metadata.stage, render.metadata.params);
    for (const auto& [name, image] : reference.patterns) input.patterns[name] = &image;
    result.diagnosis = diagnoseDifference(input, result.comparison, settings);
    // Far noisier than any valid method: unless the difference has a pattern of its own (a
    // missing cosine is both wrong and noisier), the case names the technique left out. Noise
    // that far past the whole-image tests' allowance fails them too, and no pattern explains it.
    const Comparison& c = result.comparison;
    const LikelyCause cause = result.diagnosis->cause;
    const bool noPattern =
        cause == LikelyCause::Unknown || cause == LikelyCause::Noise || cause == LikelyCause::Local;
    if (c.tooNoisy() && (c.meanAgrees(settings) || noPattern))
      result.diagnosis = Diagnosis{LikelyCause::Noise, 1.0, result.comparison.requiredTechnique};
  }
  if (!result.todos.empty()) {
    // A placeholder can be right by chance (the box filter's is); unfinished work never passes.
    result.passed = false;
    result.problem = "your stage is unfinished: its TODOs ran (listed below)";
  }
}

double casePoints(int index, int count) {
  // Whole hundredths: the first (total mod count) cases take one hundredth more.
  const long total = std::lround(100.0 * kPointsPerStage);
  return static_cast<double>(total / count + (index < total % count ? 1 : 0)) / 100.0;
}

GradeSummary gradeStages(const GradingRun& run, const ComparisonSettings& settings) {
  const auto start = std::chrono::steady_clock::now();
  GradeSummary summary;
  summary.title = std::string("Pathway grading: ") +
                  (run.gradeReference ? "the reference stages themselves"
                   : run.together     ? "your stages together"
                                      : "each stage on the reference's earlier stages");
  // What the children will be shut in with, said before any of them runs (and refused here, not
  // in every child, where --sandbox require cannot be met).
  CaseRenderJob probe;
  for (const GradingCase* c : run.cases) probe.cases.push_back({c, run.timeLimit});
  summary.sandbox = probeSandbox(probe.sandboxPolicy(), run.sandbox).summary();
  // The renders and their logs, removed at the end: somewhere a child of a root grader (nobody)
  // can reach its own folder in, which others may pass through but not list.
  const TemporaryFolder work("pathway-grade", sandboxTemporaryRoot());
  fs::permissions(work.path(),
                  fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  std::vector<std::string> sandboxSeen;
  // The stage libraries, copied where the sandbox's user can read them (wherever they were
  // built: a tree in /root, an output under a 0700 folder).
  GradingRun staged = run;
  const fs::path libraries = fs::path(work.path()) / "libraries";
  fs::create_directory(libraries);
  fs::permissions(libraries, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  for (size_t i = 0; i < staged.stageLibraries.size(); ++i) {
    const fs::path copy = libraries / (std::to_string(i) + "-" +
                                       fs::path(staged.stageLibraries[i]).filename().string());
    // A library in a folder its compiler could write: never followed through a link. One that
    // cannot be copied stays where it is: the child says why it cannot load it.
    if (copyRegularFile(staged.stageLibraries[i], copy)) staged.stageLibraries[i] = copy.string();
  }
  std::map<int, int> casesPerStage, done;
  for (const GradingCase* c : run.cases) ++casesPerStage[c->stage];
  // A stage's cases (consecutive in the run) render in one child, unless one crashes or hangs.
  for (size_t first = 0; first < run.cases.size();) {
    size_t end = first;
    while (end < run.cases.size() && run.cases[end]->stage == run.cases[first]->stage) ++end;
    std::vector<CaseResult> results;
    std::vector<std::optional<GradingReference>> references;
    std::vector<CaseRenderJob::Case> toRender;
    for (size_t i = first; i < end; ++i) {
      results.push_back(caseHeader(*run.cases[i]));
      try {
        references.push_back(
            readGradingReference(run.references + "/" + run.cases[i]->referenceFile()));
        toRender.push_back({run.cases[i], caseLimit(run, *references.back())});
      } catch (const std::exception& error) {
        references.emplace_back();
        results.back().problem = error.what();
      }
    }
    if (run.progress)
      std::fprintf(stderr, "grading stage %d: %zu cases ...\n", run.cases[first]->stage,
                   end - first);
    const std::vector<RenderOutcome> outcomes =
        renderInChildren(toRender, staged, run.seed, work.path(), &sandboxSeen);
    for (size_t i = first, rendered = 0; i < end; ++i) {
      CaseResult& result = results[i - first];
      if (const auto& reference = references[i - first]) {
        gradeCase(result, *run.cases[i], staged, *reference, toRender[rendered].timeLimit,
                  outcomes[rendered], work.path(), settings);
        ++rendered;
      }
      result.maxPoints =
          casePoints(done[run.cases[i]->stage]++, casesPerStage[run.cases[i]->stage]);
      result.points = result.passed ? result.maxPoints : 0.0;
      summary.cases.push_back(std::move(result));
    }
    const int stage = run.cases[first]->stage;
    if (run.warpTests && hasWarpTest(stage))
      summary.checks.push_back(warpTestInChild(stage, staged, work.path(), &sandboxSeen));
    first = end;
  }
  // What held, as the children said it from inside before any student code ran (the probe above
  // is what this machine promised).
  std::vector<std::string> held;
  for (std::string line : sandboxSeen) {
    if (line.rfind("pathway: ", 0) == 0) line.erase(0, 9);
    // Each child's CPU limit is its own cases' time limits: one line serves them all.
    line = std::regex_replace(line, std::regex("CPU [0-9]+ s"), "CPU time of its cases' limits");
    while (!line.empty() && line.back() == '\n') line.pop_back();
    if (std::find(held.begin(), held.end(), line) == held.end()) held.push_back(line);
  }
  if (!held.empty()) {
    summary.sandbox.clear();
    for (const std::string& line : held)
      summary.sandbox += (summary.sandbox.empty() ? "" : "\n") + line;
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

bool usedNextEventEstimation(int stage, const std::string& renderedParams) {
  if (stage < 1 || stage > kStageCount) return true;  // no stage's option to say otherwise
  const OptionSpec* nee = optionWithRole(stageInfo(stage).params, OptionRole::NextEventEstimation);
  if (!nee) return false;
  ParamValues values({*nee});  // its default, unless the render lists a value it accepts
  try {
    const std::map<std::string, std::string> given = parseParamList(renderedParams);
    if (const auto listed = given.find(nee->name); listed != given.end())
      values.setText("the render's metadata", nee->name, listed->second);
  } catch (const PathwayError&) {
    // metadata no render writes: the default stands
  }
  return values.number(nee->name) != 0.0;
}

}  // namespace pathway
