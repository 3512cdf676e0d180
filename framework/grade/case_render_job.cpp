#include "grade/case_render_job.h"

#include <unistd.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <thread>

#include "core/child_process.h"
#include "core/error.h"
#include "engine/pixel_in_progress.h"
#include "grade/jackknife_render.h"
#include "grade/stage_warp_test.h"
#include "io/image_io.h"
#include "scene/gltf_loader.h"
#include "stage_loading/reference_library.h"
#include "stage_loading/stage_library.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

// The job's options: written by toArguments, read by fromArguments, used nowhere else.
constexpr const char* kOutputFlag = "--output";                   // once
constexpr const char* kScenesFlag = "--scenes";                   // once
constexpr const char* kSeedFlag = "--seed";                       // once
constexpr const char* kCaseFlag = "--case";                       // per case, in order ...
constexpr const char* kTimeLimitFlag = "--time-limit";            // ... each followed by its limit
constexpr const char* kTogetherFlag = "--together";               // a toggle (present or not)
constexpr const char* kGradeReferenceFlag = "--grade-reference";  // a toggle (present or not)
constexpr const char* kSingleRayFlag = "--single-ray";            // a toggle (present or not)
constexpr const char* kStagesLibraryFlag = "--stages-library";    // per library, in order
constexpr const char* kSandboxFlag = "--sandbox";                 // once
constexpr const char* kReferenceStageFlag = "--reference-stage";  // per stage, in order
constexpr const char* kReferenceFolderFlag = "--reference-folder";  // once, with the stages
constexpr const char* kReportFlag = "--report-sandbox";             // a toggle (present or not)
constexpr const char* kWarpTestFlag = "--warp-test";                // once, with the stage

// The child's limits: a render and its log need far less than 64 MiB of file, and the largest
// grading case far less than 4 GiB of address space (thread stacks and malloc's arenas
// included); a grace on top of the cases' time limits.
constexpr uint64_t kChildFileBytes = 64ull << 20;
constexpr uint64_t kChildAddressSpaceBytes = 4ull << 30;
constexpr uint64_t kChildOpenFiles = 256;
constexpr double kChildCpuGraceSeconds = 10.0;

// The shortest text that reads back as the same double (15 -> "15", 17.25 -> "17.25").
std::string exactText(double value) {
  char text[64];
  const std::to_chars_result written = std::to_chars(text, text + sizeof text, value);
  return std::string(text, written.ptr);
}

// `text` whole as a number, or false.
template <typename T>
bool readNumber(const std::string& text, T& value) {
  const char* end = text.data() + text.size();
  const std::from_chars_result read = std::from_chars(text.data(), end, value);
  return !text.empty() && read.ec == std::errc() && read.ptr == end;
}

PathwayError refusal(const std::string& problem) {
  return PathwayError(std::string(CaseRenderJob::kCommand) + ": " + problem);
}

}  // namespace

std::vector<std::string> CaseRenderJob::toArguments() const {
  std::vector<std::string> arguments = {kCommand,  kOutputFlag,         output, kScenesFlag, scenes,
                                        kSeedFlag, std::to_string(seed)};
  for (const Case& c : cases)
    arguments.insert(arguments.end(),
                     {kCaseFlag, c.gradingCase->id(), kTimeLimitFlag, exactText(c.timeLimit)});
  if (together) arguments.push_back(kTogetherFlag);
  if (gradeReference) arguments.push_back(kGradeReferenceFlag);
  if (singleRay) arguments.push_back(kSingleRayFlag);
  for (const std::string& library : stageLibraries)
    arguments.insert(arguments.end(), {kStagesLibraryFlag, library});
  for (int stage : referenceStages)
    arguments.insert(arguments.end(), {kReferenceStageFlag, std::to_string(stage)});
  if (!referenceFolder.empty())
    arguments.insert(arguments.end(), {kReferenceFolderFlag, referenceFolder});
  if (reportsSandbox) arguments.push_back(kReportFlag);
  if (warpTestStage != 0)
    arguments.insert(arguments.end(), {kWarpTestFlag, std::to_string(warpTestStage)});
  arguments.insert(arguments.end(), {kSandboxFlag, sandboxModeName(sandbox)});
  return arguments;
}

CaseRenderJob CaseRenderJob::fromArguments(const std::vector<std::string>& arguments) {
  if (arguments.empty() || arguments.front() != kCommand)
    throw refusal("the command line does not start with " + std::string(kCommand));
  CaseRenderJob job;
  std::set<std::string> given;  // the options that may be given once
  for (size_t i = 1; i < arguments.size(); ++i) {
    const std::string& flag = arguments[i];
    const auto once = [&] {
      if (!given.insert(flag).second) throw refusal(flag + " is given twice");
    };
    const auto value = [&]() -> const std::string& {
      if (i + 1 == arguments.size() || arguments[i + 1].empty())
        throw refusal(flag + " needs a value");
      return arguments[++i];
    };
    if (flag == kOutputFlag) {
      once();
      job.output = value();
    } else if (flag == kScenesFlag) {
      once();
      job.scenes = value();
    } else if (flag == kSeedFlag) {
      once();
      const std::string& text = value();
      if (!readNumber(text, job.seed))
        throw refusal(flag + " '" + text + "' is not a seed (a whole number from 0)");
    } else if (flag == kCaseFlag) {
      const std::string& id = value();
      try {
        job.cases.push_back({&findGradingCase(id), 0.0});
      } catch (const PathwayError& error) {
        throw refusal(flag + ": " + error.what());
      }
    } else if (flag == kTimeLimitFlag) {
      if (job.cases.empty() || job.cases.back().timeLimit > 0.0)
        throw refusal(flag + " must follow a " + kCaseFlag + " of its own");
      const std::string& text = value();
      double& limit = job.cases.back().timeLimit;
      if (!readNumber(text, limit) || !std::isfinite(limit) || limit <= 0.0)
        throw refusal(flag + " '" + text + "' is not a positive number of seconds");
    } else if (flag == kTogetherFlag) {
      once();
      job.together = true;
    } else if (flag == kGradeReferenceFlag) {
      once();
      job.gradeReference = true;
    } else if (flag == kSingleRayFlag) {
      once();
      job.singleRay = true;
    } else if (flag == kStagesLibraryFlag) {
      job.stageLibraries.push_back(value());
    } else if (flag == kReferenceStageFlag) {
      const std::string& text = value();
      int stage = 0;
      if (!readNumber(text, stage) || stage < 1 || stage > kStageCount)
        throw refusal(flag + " '" + text + "' is not a stage (1 to " + std::to_string(kStageCount) +
                      ")");
      job.referenceStages.push_back(stage);
    } else if (flag == kReferenceFolderFlag) {
      once();
      job.referenceFolder = value();
    } else if (flag == kReportFlag) {
      once();
      job.reportsSandbox = true;
    } else if (flag == kWarpTestFlag) {
      once();
      const std::string& text = value();
      if (!readNumber(text, job.warpTestStage) || !hasWarpTest(job.warpTestStage))
        throw refusal(flag + " '" + text + "' is not a stage with a warp test (2 or 5)");
    } else if (flag == kSandboxFlag) {
      once();
      try {
        job.sandbox = parseSandboxMode(value());
      } catch (const PathwayError& error) {
        throw refusal(flag + ": " + error.what());
      }
    } else {
      throw refusal("unknown argument '" + flag + "'");
    }
  }
  for (const char* required : {kOutputFlag, kScenesFlag, kSeedFlag, kSandboxFlag})
    if (!given.count(required)) throw refusal(std::string("no ") + required + " given");
  if (job.cases.empty() && job.warpTestStage == 0)
    throw refusal(std::string("no ") + kCaseFlag + " or " + kWarpTestFlag + " given");
  if (!job.referenceStages.empty() && job.referenceFolder.empty())
    throw refusal(std::string(kReferenceStageFlag) + " needs a " + kReferenceFolderFlag);
  for (const Case& c : job.cases)
    if (c.timeLimit <= 0.0)
      throw refusal(std::string(kCaseFlag) + " " + c.gradingCase->id() + " has no " +
                    kTimeLimitFlag);
  return job;
}

std::string CaseRenderJob::imagePath(const GradingCase& gradingCase) const {
  return output + "/" + gradingCase.id() + "-" + std::to_string(seed) + ".exr";
}

std::string CaseRenderJob::warpTestPath() const {
  return output + "/warptest-stage" + std::to_string(warpTestStage) + "-" + std::to_string(seed) +
         ".txt";
}

bool operator==(const CaseRenderJob::Case& a, const CaseRenderJob::Case& b) {
  return a.gradingCase == b.gradingCase && a.timeLimit == b.timeLimit;
}

bool operator==(const CaseRenderJob& a, const CaseRenderJob& b) {
  return a.cases == b.cases && a.output == b.output && a.scenes == b.scenes && a.seed == b.seed &&
         a.together == b.together && a.gradeReference == b.gradeReference &&
         a.singleRay == b.singleRay && a.stageLibraries == b.stageLibraries &&
         a.referenceStages == b.referenceStages && a.referenceFolder == b.referenceFolder &&
         a.reportsSandbox == b.reportsSandbox && a.sandbox == b.sandbox &&
         a.warpTestStage == b.warpTestStage;
}

std::vector<int> CaseRenderJob::referenceStagesFor(int stage, bool gradeReference, bool together) {
  std::vector<int> stages;
  if (together && !gradeReference) return stages;
  for (int earlier = 1; earlier < stage + (gradeReference ? 1 : 0); ++earlier)
    stages.push_back(earlier);
  return stages;
}

SandboxPolicy CaseRenderJob::sandboxPolicy() const {
  SandboxPolicy policy;
  policy.readable = stageLibraries;
  policy.writable = {output};
  policy.removesFiles = false;  // what it wrote stays there for the grader's quota to count
  double seconds = kChildCpuGraceSeconds;
  for (const Case& c : cases) seconds += c.timeLimit;
  if (warpTestStage != 0) seconds += kWarpTestSeconds;
  policy.cpuSeconds =
      static_cast<uint64_t>(std::ceil(seconds * std::max(1u, std::thread::hardware_concurrency())));
  policy.addressSpaceBytes = kChildAddressSpaceBytes;
  policy.openFiles = kChildOpenFiles;
  policy.fileBytes = kChildFileBytes;
  return policy;
}

void runCaseRenderJob(const CaseRenderJob& job) {
  limitThisChild(kChildFileBytes);
  reportPixelsOnFatalSignals();
  // Everything the cases read from files, read while this process is still the grader's own.
  std::map<std::string, Scene> scenes;
  for (const CaseRenderJob::Case& c : job.cases)
    if (!scenes.count(c.gradingCase->scene))
      scenes.emplace(c.gradingCase->scene, loadScene(job.scenes + "/" + c.gradingCase->scene));
  if (job.warpTestStage == 5 && !scenes.count(kWarpTestScene))
    scenes.emplace(kWarpTestScene, loadScene(job.scenes + "/" + kWarpTestScene));
  // The reference stages the job may hold: trusted code, loaded (and sealed, checked) while this
  // process is still the grader's own.
  for (int stage : job.referenceStages)
    loadReferenceStageLibrary(referenceStageLibrary(stage, job.referenceFolder), stage);
  // Shut in before the first line of student code runs: loading a library runs its static
  // initializers. No thread has started yet (the renderer's start with the first case).
  const SandboxState sandbox = enterSandbox(job.sandboxPolicy(), job.sandbox);
  const std::string said = "pathway: " + sandbox.summary() + "\n";
  std::fputs(said.c_str(), stdout);
  std::fflush(stdout);
  if (job.reportsSandbox) {
    // The parent's record of what held, written before student code could write anything.
    if (::write(kChildReportDescriptor, said.data(), said.size()) < 0) {
      // the parent is gone: nothing to tell
    }
    ::close(kChildReportDescriptor);
  }
  std::vector<int> registeredStages;
  for (const std::string& library : job.stageLibraries)
    for (int stage : loadStageLibrary(library)) registeredStages.push_back(stage);
  for (const CaseRenderJob::Case& c : job.cases) {
    const GradingCase& gradingCase = *c.gradingCase;
    // The case's own deadline: past it, SIGALRM ends this process (its default action).
    alarm(static_cast<unsigned>(std::ceil(c.timeLimit)));
    if (!job.stageLibraries.empty() && std::find(registeredStages.begin(), registeredStages.end(),
                                                 gradingCase.stage) == registeredStages.end())
      throw PathwayError("no stage library given registers stage " +
                         std::to_string(gradingCase.stage) +
                         " (does its file end with its registerStage line?)");
    const RenderRecipe recipe =
        gradingCase.recipe(job.gradeReference ? Variant::Reference : Variant::Student,
                           job.together ? EarlierStages::Own : EarlierStages::Reference, job.seed,
                           job.singleRay ? ReferenceTracing::SingleRay : ReferenceTracing::Fastest);
    const RayTracer tracer(scenes.at(gradingCase.scene));
    const RenderResult result = renderWithJackknife(tracer, recipe, gradingCase.ownNoiseCounts());
    writeExr(job.imagePath(gradingCase), result.images, result.metadata);
  }
  if (job.warpTestStage != 0) {
    alarm(static_cast<unsigned>(CaseRenderJob::kWarpTestSeconds));
    const Variant variant = job.gradeReference ? Variant::Reference : Variant::Student;
    const auto lights = scenes.find(kWarpTestScene);
    const StageWarpTest outcome = runStageWarpTest(
        job.warpTestStage, variant, lights == scenes.end() ? nullptr : &lights->second,
        kWarpTestSamples, job.seed);
    const std::string text = (outcome.passed ? "passed\n" : "failed\n") + outcome.verdict + "\n";
    writeThroughTemporary(job.warpTestPath(), [&](const std::string& temporary) {
      std::ofstream out(temporary, std::ios::binary);
      out << text;
      if (!out.flush()) throw PathwayError(temporary + ": cannot write the warp test's outcome");
    });
  }
  alarm(0);
}

}  // namespace pathway
