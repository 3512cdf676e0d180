// `pathway grade`: grades stages against the course's references (docs/grading.md).
//
//   pathway grade [--stage N]... [--together]       your stages, each on its grading cases
//   pathway grade --image a.exr --reference b.exr   two files
//   pathway grade --submissions DIR                  a class: every submission folder in DIR
//   pathway grade --make-references [--stage N]...  the references, from solutions/ (instructors)
//   pathway grade --calibrate SEEDS ...              false-alarm or detection rates
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <set>

#include "app/commands.h"
#include "core/error.h"
#include "grade/class_grading.h"
#include "grade/grade_calibration.h"
#include "grade/reference_comparison.h"
#include "grade/stage_grading.h"
#include "render/integrator_registry.h"
#include "render/reference_library.h"
#include "render/stage_catalog.h"
#include "render/stage_library.h"
#include "scene/gltf_loader.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kScenesDir = PATHWAY_SOURCE_DIR "/scenes";

struct GradeOptions {
  std::vector<int> stages;  // empty: all
  std::vector<std::string> cases;
  bool together = false;
  bool gradeReference = false;
  std::vector<std::string> stageLibraries;
  std::string references = kScenesDir + "/references";
  std::string report = "grade-report";
  std::string results;  // empty: <report>/results.json
  double timeLimit = 120.0;
  uint64_t seed = kStudentSeed;
  std::string image, reference;
  std::string submissions;  // a folder of submission folders
  std::string submission;   // one submission folder
  std::string output = "grade-output";
  bool tableOnly = false;  // with --submissions: the class table from results in --output
  bool makeReferences = false;
  bool listCases = false;
  int calibrate = 0;                     // > 0: grade this many seeds per case, in this process
  std::vector<uint32_t> calibrationSpp;  // empty: each case's own
  bool quiet = false;
};

std::vector<const GradingCase*> selectedCases(const GradeOptions& options) {
  std::vector<const GradingCase*> selected;
  for (const std::string& id : options.cases) selected.push_back(&findGradingCase(id));
  if (!selected.empty()) return selected;
  std::set<int> stages(options.stages.begin(), options.stages.end());
  if (stages.empty())
    for (int stage = 1; stage <= kStageCount; ++stage) stages.insert(stage);
  for (int stage : stages)
    for (const GradingCase* c : gradingCasesOf(stage)) selected.push_back(c);
  return selected;
}

GradingRun gradingRun(const GradeOptions& options) {
  GradingRun run;
  run.cases = selectedCases(options);
  run.together = options.together;
  run.gradeReference = options.gradeReference;
  run.stageLibraries = options.stageLibraries;
  run.references = options.references;
  run.scenes = kScenesDir;
  run.timeLimit = options.timeLimit;
  run.seed = options.seed;
  run.progress = !options.quiet;
  return run;
}

int finish(const GradeSummary& summary, const GradeOptions& options,
           const ComparisonSettings& settings) {
  // results.json goes first, or into the report folder as it moves into place.
  const std::string results =
      options.results.empty() ? options.report + "/results.json" : options.results;
  if (!options.results.empty()) writeGradescopeResults(results, summary, settings);
  std::map<std::string, std::string> extra;
  if (options.results.empty()) extra["results.json"] = gradescopeResults(summary, settings);
  writeHtmlReport(options.report, summary, settings, extra);
  if (!options.quiet) {
    for (const std::string& note : summary.notes) std::printf("%s\n", note.c_str());
    for (const CaseResult& c : summary.cases)
      std::printf("%-40s %s\n", c.title.c_str(), c.passed ? "passed" : "FAILED");
    std::printf("%.1f / %.1f points; report %s/index.html, results %s\n", summary.points(),
                summary.maxPoints(), options.report.c_str(), results.c_str());
  }
  return summary.passed() ? 0 : 1;
}

int compareFiles(const GradeOptions& options) {
  const ComparisonSettings settings;
  GradeSummary summary;
  summary.title = "Pathway: " + options.image + " against " + options.reference;
  CaseResult result;
  result.id = "comparison";
  result.title = fs::path(options.image).filename().string() + " vs " +
                 fs::path(options.reference).filename().string();
  result.purpose = "two files";
  result.maxPoints = 1.0;
  try {
    const LoadedImage image = readImageFile(options.image);
    const LoadedImage reference = readImageFile(options.reference);
    if (reference.layers.count("tileVariance")) {
      judgeAgainstReference(result, image, readGradingReference(options.reference), settings);
    } else {
      // A plain render as the reference: each file's own per-pixel variance.
      result.comparison = compareWithReference(image.images, image.metadata,
                                               {reference.images, reference.metadata}, settings);
      result.compared = true;
      result.passed = result.comparison.passed(settings);
      result.image = image.images.color;
      result.reference = reference.images.color;
    }
  } catch (const PathwayError& error) {
    result.problem = error.what();
  }
  result.points = result.passed ? 1.0 : 0.0;
  summary.cases.push_back(std::move(result));
  return finish(summary, options, settings);
}

int makeReferences(const GradeOptions& options) {
  fs::create_directories(options.references);
  std::map<std::string, std::unique_ptr<Scene>> scenes;
  for (const GradingCase* c : selectedCases(options)) {
    const auto start = std::chrono::steady_clock::now();
    auto& scene = scenes[c->scene];
    if (!scene) scene = std::make_unique<Scene>(loadScene(kScenesDir + "/" + c->scene));
    const RayTracer tracer(*scene);
    const bool terminal = !options.quiet && ::isatty(STDERR_FILENO);
    const GradingReference reference = makeGradingReference(*c, tracer, [&](int done) {
      if (terminal)
        std::fprintf(stderr, "\r%-36s %2d/%d replicates", c->id().c_str(), done,
                     kReferenceReplicates);
    });
    const std::string path = options.references + "/" + c->referenceFile();
    writeGradingReference(path, reference);
    if (!options.quiet)
      std::fprintf(stderr, "%s%-36s %5.1f s -> %s\n", terminal ? "\r" : "", c->id().c_str(),
                   std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                   path.c_str());
  }
  return 0;
}

// False-alarm rate (the reference stages) or detection rate (a stage library) over many seeds.
int calibrateCases(const GradeOptions& options) {
  for (const std::string& library : options.stageLibraries) loadStageLibrary(library);
  const Variant variant = options.gradeReference ? Variant::Reference : Variant::Student;
  const ComparisonSettings settings;
  std::printf("%-32s %5s %6s %9s %9s %9s %11s %8s\n", "case", "spp", "seeds", "failures", "rate",
              "verdicts", "closest p", "seconds");
  for (const GradingCase* c : selectedCases(options)) {
    std::vector<uint32_t> spps = options.calibrationSpp;
    if (spps.empty()) spps.push_back(c->spp);
    for (uint32_t spp : spps) {
      const CalibrationResult r = calibrate(*c, spp, variant, options.calibrate, options.seed,
                                            options.references, kScenesDir, settings);
      std::string seeds;  // the first few, to look at again with --seed
      for (size_t i = 0; i < r.failedSeeds.size() && i < 5; ++i)
        seeds += (i ? "," : "  seeds ") + std::to_string(r.failedSeeds[i]);
      std::printf("%-32s %5u %6d %9d %9.4f %9d %11.3g %8.1f%s\n", r.caseId.c_str(), r.spp, r.seeds,
                  r.failures, double(r.failures) / r.seeds, r.confirmedFailures, r.largestWorstP,
                  r.seconds, seeds.c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}

int gradeSubmissions(const GradeOptions& options) {
  ClassGrading grading;
  grading.submissions = options.submissions;
  grading.output = options.output;
  grading.run = gradingRun(options);
  const std::vector<SubmissionResult> rows = options.tableOnly
                                                 ? classTableFromResults(grading)
                                                 : gradeClass(grading, ComparisonSettings());
  if (!options.quiet) {
    for (const SubmissionResult& r : rows)
      std::printf("%-24s %5.1f / %5.1f  %s\n", r.name.c_str(), r.points, r.maxPoints,
                  r.status.c_str());
    std::printf("class table: %s/index.html and %s/class.csv\n", grading.output.c_str(),
                grading.output.c_str());
  }
  return 0;
}

void listCases() {
  std::printf("%-30s %-26s %-9s %4s %4s %7s  %s\n", "case", "scene", "filter", "spp", "tile",
              "size", "parameters: what it is there to catch");
  for (const GradingCase& c : gradingCases()) {
    std::string params;
    for (const auto& [name, value] : c.params) params += name + "=" + value + " ";
    const std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
    std::printf("%-30s %-26s %-9s %4u %4d %7s  %s%s%s\n", c.id().c_str(), c.scene.c_str(),
                filterTypeName(c.filter).c_str(), c.spp, c.tileSize, size.c_str(), params.c_str(),
                c.sobol ? "(sobol) " : "", c.purpose.c_str());
  }
}

int run(const GradeOptions& options) {
  const bool writesReport = !options.makeReferences && options.calibrate == 0 &&
                            options.submissions.empty() && options.submission.empty() &&
                            !options.listCases;
  if (writesReport) checkReportFolder(options.report);  // before any work, not after it
  if (options.listCases) {
    listCases();
    return 0;
  }
  if (options.makeReferences) return makeReferences(options);
  if (options.calibrate > 0) return calibrateCases(options);
  if (options.tableOnly && options.submissions.empty())
    throw PathwayError("--table-only goes with --submissions (and --output)");
  if (!options.submissions.empty()) return gradeSubmissions(options);
  if (!options.submission.empty()) {
    const SubmissionResult result = gradeSubmission(
        options.submission, options.output, gradingRun(options), 300.0, ComparisonSettings());
    if (!options.quiet)
      std::printf("%s: %.1f / %.1f points, %s; %s/report/index.html, %s/results.json\n",
                  result.name.c_str(), result.points, result.maxPoints, result.status.c_str(),
                  options.output.c_str(), options.output.c_str());
    return result.points == result.maxPoints ? 0 : 1;
  }
  if (!options.image.empty() || !options.reference.empty()) {
    if (options.image.empty() || options.reference.empty())
      throw PathwayError("--image and --reference go together");
    return compareFiles(options);
  }
  const ComparisonSettings settings;
  GradingRun run = gradingRun(options);
  // Without reference stages (a handout whose library is missing or refused) there are none to
  // put under yours: grade yours together, and say why.
  const bool noReference = !findStageIntegrator(1, Variant::Reference);
  if (noReference) run.together = true;
  GradeSummary summary = gradeStages(run, settings);
  if (noReference && !options.together)
    summary.notes.push_back("There are no reference stages here (" + referenceStagesProblem() +
                            "), so your stages are graded together: a bug in an earlier stage "
                            "also fails the stages after it.");
  return finish(summary, options, settings);
}

}  // namespace

Command addGradeCommand(CLI::App& app) {
  auto options = std::make_shared<GradeOptions>();
  CLI::App* grade = app.add_subcommand(
      "grade", "Grade stages against the reference images (or compare two images)");
  grade->footer(
      "Examples:\n"
      "  pathway grade                                 every stage, each on the reference's\n"
      "                                                earlier stages; report in grade-report/\n"
      "  pathway grade --stage 3 --together            stage 3 on your own stages 1-2\n"
      "  pathway grade --image mine.exr --reference ref.exr\n"
      "  pathway grade --submissions class/            every submission folder in class/\n"
      "  pathway grade --submission alice/ --output out/   one submission, built and graded\n"
      "  pathway grade --make-references               (instructors: needs solutions/)\n"
      "  pathway grade --calibrate 1000 --grade-reference   false alarms over 1000 seeds");
  grade->add_option("--stage", options->stages, "Grade only these stages (repeatable)")
      ->check(CLI::Range(1, kStageCount));
  grade->add_option("--case", options->cases, "Grade only these cases, e.g. stage3-corner");
  grade->add_flag("--together", options->together,
                  "Your stages together (a bug in stage 1 shows in every stage) instead of each "
                  "stage on the reference's earlier stages");
  grade->add_option("--references", options->references, "Folder of the reference images")
      ->capture_default_str();
  grade->add_option("--report", options->report, "Folder for the HTML report (replaced)")
      ->capture_default_str();
  grade->add_option("--results", options->results,
                    "Gradescope results.json (default: in the report folder)");
  grade->add_option("--time-limit", options->timeLimit, "Seconds one case may render")
      ->check(CLI::Range(1.0, 86400.0))
      ->capture_default_str();
  grade
      ->add_option("--seed", options->seed,
                   "Seed of the graded renders (the references use others)")
      ->capture_default_str();
  grade->add_option("--image", options->image, "Compare this EXR ...");
  grade->add_option("--reference", options->reference,
                    "... with this one (a grading reference, or a render with variance)");
  grade->add_option("--submissions", options->submissions,
                    "Grade every submission folder in this folder (a copy of assignments/ or "
                    "just the stage files each)");
  grade->add_option("--submission", options->submission,
                    "Build and grade one submission folder (what Gradescope's autograder runs)");
  grade
      ->add_option("--output", options->output,
                   "With --submission(s): where builds, reports, results and the class table go")
      ->capture_default_str();
  grade->add_flag("--table-only", options->tableOnly,
                  "With --submissions: write the class table from the results already in "
                  "--output, grading nothing (pathway cluster grade's last step)");
  grade->add_option("--stages-library", options->stageLibraries,
                    "Grade the stages of this library (student stage files compiled on their own; "
                    "repeatable)");
  grade->add_flag("--grade-reference", options->gradeReference,
                  "Grade the reference stages instead of yours (false-alarm checks)");
  grade->add_flag("--list-cases", options->listCases,
                  "List the grading cases: scene, settings, what each is there to catch");
  grade->add_flag("--make-references", options->makeReferences,
                  "Render the references from solutions/ into --references");
  grade
      ->add_option("--calibrate", options->calibrate,
                   "Grade this many fresh seeds per case in one process and print the failure "
                   "rate (with --grade-reference: false alarms; with a library: detections)")
      ->check(CLI::Range(1, 1000000));
  grade
      ->add_option("--calibrate-spp", options->calibrationSpp,
                   "With --calibrate: these spp instead of each case's (references made first)")
      ->check(CLI::Range(1u, 1u << 16));
  grade->add_flag("-q,--quiet", options->quiet, "No progress or summary");
  return {grade, [options] { return run(*options); }};
}

}  // namespace pathway
