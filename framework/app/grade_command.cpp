// `pathway grade`: grades stages against the course's references (docs/grading.md). This file
// declares the options and picks the mode they ask for; each mode is a file of its own
// (grade_modes.h).
//
//   pathway grade [--stage N]... [--together]       your stages, each on its grading cases
//   pathway grade --image a.exr --reference b.exr   two files
//   pathway grade --submissions DIR                  a class: every submission folder in DIR
//   pathway grade --submission DIR                   one submission (Gradescope's autograder)
//   pathway grade --make-references [--stage N]...  the references, from solutions/ (instructors)
//   pathway grade --calibrate SEEDS ...              false-alarm or detection rates
//   pathway grade --list-cases                       the grading cases
#include <algorithm>
#include <iterator>
#include <memory>

#include "app/commands.h"
#include "app/grade_modes.h"
#include "app/shared_options.h"
#include "core/error.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

// What a mode does with --report (writes it: its folder is checked before any work, not after it)
// and with --table-only (it belongs to the class mode; the modes after that one refuse it).
enum class Report { None, Written };
enum class TableOnly { Ignored, Taken, Refused };

struct GradeMode {
  int (*run)(const GradeOptions&);
  Report report;
  TableOnly tableOnly;
  bool (*chosen)(const GradeOptions&);
};

// The modes, in the order they are tried: the first one chosen runs. The last is always chosen.
const GradeMode kGradeModes[] = {
    {listCasesMode, Report::None, TableOnly::Ignored,  //
     [](const GradeOptions& o) { return o.listCases; }},
    {makeReferencesMode, Report::None, TableOnly::Ignored,  //
     [](const GradeOptions& o) { return o.makeReferences; }},
    {calibrateMode, Report::None, TableOnly::Ignored,  //
     [](const GradeOptions& o) { return o.calibrate > 0; }},
    {gradeClassMode, Report::None, TableOnly::Taken,  //
     [](const GradeOptions& o) { return !o.submissions.empty(); }},
    {gradeSubmissionMode, Report::None, TableOnly::Refused,  //
     [](const GradeOptions& o) { return !o.submission.empty(); }},
    {compareFilesMode, Report::Written, TableOnly::Refused,  //
     [](const GradeOptions& o) { return !o.image.empty() || !o.reference.empty(); }},
    {gradeStagesMode, Report::Written, TableOnly::Refused,  //
     [](const GradeOptions&) { return true; }},
};

int run(const GradeOptions& options) {
  const GradeMode& mode =
      *std::find_if(std::begin(kGradeModes), std::end(kGradeModes),
                    [&](const GradeMode& candidate) { return candidate.chosen(options); });
  if (mode.report == Report::Written) checkReportFolder(options.report);
  if (mode.tableOnly == TableOnly::Refused && options.tableOnly)
    throw PathwayError("--table-only goes with --submissions (and --output)");
  if (options.verdictSeeds && options.calibrate == 0)
    throw PathwayError("--verdict-seeds goes with --calibrate");
  return mode.run(options);
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
  addOption(*grade,
            setting::kSeed.withDefault(kStudentSeed,
                                       "Seed of the graded renders (the references use "
                                       "others)"),
            options->seed);
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
  grade->add_flag("--single-ray", options->singleRay,
                  "Render references (--make-references, --calibrate, --grade-reference) with "
                  "stageN@ref, one ray at a time, even where the faster stageN@fast exists");
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
  grade->add_flag("--verdict-seeds", options->verdictSeeds,
                  "With --calibrate: after each case's row, a line 'verdict seeds: S ...' with "
                  "every seed whose failure was confirmed (scripts/power reads it)");
  grade
      ->add_option_function<std::string>(
          "--sandbox",
          [options](const std::string& name) { options->sandbox = parseSandboxMode(name); },
          "How student code is shut in while it compiles and renders: require (refuse to grade "
          "where the kernel cannot), auto (what the kernel allows) or off (debugging)")
      ->check(CLI::IsMember({"require", "auto", "off"}))
      ->default_str(sandboxModeName(SandboxMode::Auto));
  grade->add_flag("-q,--quiet", options->quiet, "No progress or summary");
  return {grade, [options] { return run(*options); }};
}

}  // namespace pathway
