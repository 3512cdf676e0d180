// `pathway cluster render|grade`: the jobs that outgrow one machine, as cluster jobs
// (cluster/cluster_job.h): on this machine by default, on Slurm with --scheduler slurm.
//
//   pathway cluster render --tasks 8 --spp 65536 -o ref.exr -- scene.gltf -i stage5@ref
//       the render split into 8 sample ranges, each task writing a part; then `pathway merge`
//   pathway cluster grade --submissions class/ --tasks 20 --output grades/ -- --time-limit 60
//       the class split into 20 chunks of submissions; then the class table
#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/commands.h"
#include "app/shared_options.h"
#include "cluster/cluster_job.h"
#include "cluster/command_lines.h"
#include "core/child_process.h"
#include "core/error.h"
#include "grade/class_grading.h"
#include "io/image_io.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

struct SchedulerChoices {
  std::string scheduler = "local";
  SchedulerOptions options;
  int tasks = 8;
  std::string workDir;
  bool quiet = false;
};

struct ClusterRenderOptions {
  SchedulerChoices job;
  uint32_t spp = setting::kSamplesPerPixel.defaultAs<uint32_t>();
  float exposure = setting::kExposure.defaultAs<float>();
  std::vector<std::string> outputs;
  std::vector<std::string> renderArguments;  // the scene and render options, after --
  bool singleRay = false;  // keep stageN@ref rather than its wavefront version stageN@fast
};

struct ClusterGradeOptions {
  SchedulerChoices job;
  std::string submissions;
  std::string output = "grade-output";
  std::vector<std::string> gradeArguments;  // grade options for every submission, after --
};

void addSchedulerOptions(CLI::App& command, SchedulerChoices& choices) {
  SchedulerOptions& o = choices.options;
  command.add_option("--scheduler", choices.scheduler, "local (worker processes here) or slurm")
      ->check(CLI::IsMember({"local", "slurm"}))
      ->capture_default_str();
  command.add_option("--tasks", choices.tasks, "Tasks the work is split into (array tasks)")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command.add_option("--work-dir", choices.workDir,
                     "Folder of the job's scripts, logs and parts (on a cluster: storage every "
                     "node sees)");
  command.add_option("--workers", o.workers, "local: tasks at once (0: one per core)")
      ->check(CLI::Range(0, 1024))
      ->capture_default_str();
  command
      .add_option("--cpus-per-task", o.cpusPerTask,
                  "CPUs each task uses (slurm: --cpus-per-task; renders use this many threads)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  command
      .add_option("--task-time-limit", o.taskTimeLimit,
                  "Seconds a task may run before it is stopped (0: no limit; slurm: --time)")
      ->check(CLI::Range(0.0, 1e7))
      ->capture_default_str();
  command.add_option("--retries", o.retries, "Times a failed task runs again")
      ->check(CLI::Range(0, 10))
      ->capture_default_str();
  command.add_option("--partition", o.partition, "slurm: the partition (queue) to submit to");
  command.add_option("--account", o.account, "slurm: the account to charge");
  command
      .add_option("--max-running", o.maxRunning,
                  "slurm: array tasks running at once (0: as many as the cluster gives)")
      ->check(CLI::Range(0, 100000));
  command.add_option(
      "--sbatch-arg", o.sbatchArguments,
      "slurm: one more sbatch option, as it is (repeatable), e.g. --sbatch-arg=--qos=short");
  command.add_flag("-q,--quiet", choices.quiet, "No progress lines");
}

SchedulerOptions schedulerOptions(const SchedulerChoices& choices) {
  SchedulerOptions options = choices.options;
  options.kind = choices.scheduler == "slurm" ? SchedulerKind::Slurm : SchedulerKind::Local;
  options.progress = !choices.quiet;
  return options;
}

std::string quoted(const std::vector<std::string>& words) {
  std::string line;
  for (const std::string& word : words) line += (line.empty() ? "" : " ") + shellQuote(word);
  return line;
}

// The whole command line of `command` (cluster/command_lines.h), run by this program.
template <typename PathwayCommand>
std::vector<std::string> commandLine(const PathwayCommand& command) {
  std::vector<std::string> words = command.toArguments();
  words.insert(words.begin(), currentExecutable());
  return words;
}

// Runs `check` (a command that only checks what every task will be given) once, here: when the
// `command` options `passedOn` are refused, nothing is submitted and its message says why.
void checkBeforeSubmitting(const std::vector<std::string>& check, const fs::path& work,
                           const std::string& command, const std::vector<std::string>& passedOn) {
  constexpr double kCheckTimeLimit = 600.0;  // it loads the scene and builds its BVH
  const ChildOutcome checked = runChild(check, kCheckTimeLimit, (work / "logs/check.log").string());
  if (!checked.succeeded())
    throw PathwayError("the " + command + " options were refused (" + quoted(passedOn) + "):\n" +
                       checked.output);
}

void printFailures(const JobOutcome& outcome) {
  for (const TaskOutcome* task : outcome.failedTasks()) {
    std::fprintf(stderr, "pathway: %s\n", describeFailure(*task).c_str());
    for (size_t i = 0; i + 1 < task->failures.size(); ++i)
      std::fprintf(stderr, "  earlier attempt: %s\n", task->failures[i].c_str());
  }
}

// Earlier attempts that failed although the task then succeeded: reported, not hidden.
void printRetried(const JobOutcome& outcome) {
  for (const TaskOutcome& task : outcome.tasks)
    if (task.succeeded && !task.failures.empty())
      std::printf("task %d failed, then succeeded on attempt %d: %s\n", task.index, task.attempts,
                  task.failures.front().c_str());
}

int runClusterRender(const ClusterRenderOptions& options) {
  if (options.renderArguments.empty())
    throw PathwayError(
        "cluster render: give the scene and render options after --, e.g. "
        "pathway cluster render -o ref.exr -- scene.gltf -i stage5@ref");
  for (const std::string& output : options.outputs) checkImagePath(output);
  const uint32_t tasks = static_cast<uint32_t>(options.job.tasks);
  if (tasks > options.spp)
    throw PathwayError("--tasks " + std::to_string(tasks) + " is more than the " +
                       std::to_string(options.spp) + " samples to split");
  const fs::path first(options.outputs.front());
  const fs::path work =
      fs::absolute(options.job.workDir.empty()
                       ? first.parent_path() / (first.stem().string() + ".cluster")
                       : fs::path(options.job.workDir))
          .lexically_normal();
  fs::create_directories(work / "parts");
  fs::create_directories(work / "logs");

  const std::vector<std::string> renderArguments =
      options.singleRay ? options.renderArguments : withFastestReference(options.renderArguments);
  // Every task gets the same render: check it here once, before anything is submitted.
  RenderPartCommand check;
  check.renderArguments = renderArguments;
  check.spp = options.spp;
  check.sampleEnd = options.spp;
  check.checkOnly = true;
  check.output = (work / "parts/check.exr").string();
  checkBeforeSubmitting(commandLine(check), work, "render", renderArguments);

  const SchedulerOptions scheduler = schedulerOptions(options.job);
  ClusterJob job;
  job.name = "pathway-render";
  job.folder = work.string();
  MergeCommand merge;
  merge.quiet = true;
  merge.exposure = options.exposure;
  std::vector<std::string> ranges;  // of each task
  for (uint32_t i = 0; i < tasks; ++i) {
    RenderPartCommand part;
    part.renderArguments = renderArguments;
    part.spp = options.spp;
    part.sampleBegin = static_cast<uint32_t>(uint64_t(options.spp) * i / tasks);
    part.sampleEnd = static_cast<uint32_t>(uint64_t(options.spp) * (i + 1) / tasks);
    part.threads = scheduler.cpusPerTask;
    part.quiet = true;
    char name[32];
    std::snprintf(name, sizeof name, "part-%04u.exr", i);
    part.output = (work / "parts" / name).string();
    job.tasks.push_back({quoted(commandLine(part))});
    merge.parts.push_back(part.output);
    ranges.push_back(std::to_string(part.sampleBegin) + ":" + std::to_string(part.sampleEnd));
  }
  for (const std::string& output : options.outputs)
    merge.outputs.push_back(fs::absolute(output).string());
  job.finish = {quoted(commandLine(merge))};

  const JobOutcome outcome = runClusterJob(job, scheduler);
  printRetried(outcome);
  if (!outcome.finishRan) {
    printFailures(outcome);
    for (const TaskOutcome* task : outcome.failedTasks())
      std::fprintf(stderr, "pathway: samples %s are missing (task %d)\n",
                   ranges[task->index].c_str(), task->index);
    std::fprintf(stderr,
                 "pathway: the image was not merged; the parts that finished are in %s/parts\n",
                 job.folder.c_str());
    return 1;
  }
  if (!outcome.finishSucceeded)
    throw PathwayError("merging the parts " + outcome.finishReason + " (log " + outcome.finishLog +
                       ")");
  if (!options.job.quiet)
    std::printf("rendered %u samples in %u tasks and merged them in %.1f s\n", options.spp, tasks,
                outcome.seconds);
  for (const std::string& output : options.outputs) std::printf("wrote %s\n", output.c_str());
  return 0;
}

int runClusterGrade(const ClusterGradeOptions& given) {
  // A class graded on shared machines runs its students' code shut in, or not at all, unless the
  // grade options say otherwise (core/sandbox.h).
  ClusterGradeOptions options = given;
  if (std::find(options.gradeArguments.begin(), options.gradeArguments.end(), "--sandbox") ==
      options.gradeArguments.end())
    options.gradeArguments.insert(options.gradeArguments.end(), {"--sandbox", "require"});
  const std::vector<std::string> folders = submissionFolders(options.submissions);
  const size_t tasks = std::min<size_t>(options.job.tasks, folders.size());
  const fs::path output = fs::absolute(options.output).lexically_normal();
  const fs::path work =
      options.job.workDir.empty() ? output / "cluster" : fs::absolute(options.job.workDir);
  fs::create_directories(work / "logs");

  // Every submission gets the same grade options: check them once, before anything is submitted.
  GradeOptionsCheckCommand check;
  check.gradeArguments = options.gradeArguments;
  checkBeforeSubmitting(commandLine(check), work, "grade", options.gradeArguments);

  ClusterJob job;
  job.name = "pathway-grade";
  job.folder = work.string();
  for (size_t i = 0; i < tasks; ++i) {
    std::vector<std::string> lines;
    for (size_t k = folders.size() * i / tasks; k < folders.size() * (i + 1) / tasks; ++k) {
      const fs::path folder = fs::absolute(folders[k]);
      SubmissionGradeCommand grade;
      grade.quiet = true;
      grade.submission = folder.string();
      grade.output = (output / folder.filename()).string();
      grade.gradeArguments = options.gradeArguments;
      // A grader that ends with points lost still writes the submission's row: a verdict. With
      // no fresh row (the row of an earlier run removed first) the task failed.
      const std::string row = shellQuote((output / folder.filename() / "submission.tsv").string());
      lines.push_back("rm -f " + row);
      lines.push_back(quoted(commandLine(grade)) + " || test -f " + row);
    }
    job.tasks.push_back(lines);
  }
  ClassTableCommand table;
  table.quiet = true;
  table.submissions = fs::absolute(options.submissions).string();
  table.output = output.string();
  job.finish = {quoted(commandLine(table))};

  const JobOutcome outcome = runClusterJob(job, schedulerOptions(options.job));
  printRetried(outcome);
  ClassGrading grading;
  grading.submissions = options.submissions;
  grading.output = output.string();
  // The finishing job wrote the table; when it did not run, write it here from what was graded.
  const bool tableWritten = outcome.finishRan && outcome.finishSucceeded;
  const std::vector<SubmissionResult> rows =
      tableWritten ? readClassResults(grading) : classTableFromResults(grading);
  for (const SubmissionResult& r : rows)
    std::printf("%-24s %5.1f / %5.1f  %-44s %s\n", r.name.c_str(), r.points, r.maxPoints,
                r.status.c_str(), (output / r.name / "results.json").string().c_str());
  std::printf("class table: %s/index.html and %s/class.csv\n", output.c_str(), output.c_str());
  if (!tableWritten) {
    printFailures(outcome);
    if (outcome.finishRan)
      std::fprintf(stderr, "pathway: the class table job %s (log %s)\n",
                   outcome.finishReason.c_str(), outcome.finishLog.c_str());
    return 1;
  }
  return 0;
}

}  // namespace

std::vector<std::string>& passedOnArguments() {
  static std::vector<std::string> arguments;
  return arguments;
}

Command addClusterCommand(CLI::App& app) {
  auto render = std::make_shared<ClusterRenderOptions>();
  auto grade = std::make_shared<ClusterGradeOptions>();
  CLI::App* cluster = app.add_subcommand(
      "cluster", "Split a render or a class's grading into tasks: here, or on a Slurm cluster");
  cluster->require_subcommand(1);
  cluster->footer(
      "Examples:\n"
      "  pathway cluster render --tasks 8 --spp 4096 -o ref.exr -- scenes/cornell_box.gltf -i "
      "stage5@ref\n"
      "  pathway cluster render --scheduler slurm --partition short --tasks 64 --spp 65536 "
      "-o ref.exr -- scene.gltf -i stage5@ref\n"
      "  pathway cluster grade --submissions class/ --scheduler slurm --tasks 20 --output grades/ "
      "-- "
      "--time-limit 60");

  CLI::App* renderCommand = cluster->add_subcommand(
      "render", "Render in --tasks sample ranges, then merge the parts into the image");
  addSchedulerOptions(*renderCommand, render->job);
  addOption(*renderCommand, setting::kSamplesPerPixel, render->spp);
  addOption(*renderCommand, setting::kExposure, render->exposure);
  renderCommand->add_option("-o,--output", render->outputs, "The merged image(s): .exr or .png")
      ->required();
  renderCommand->add_flag("--single-ray", render->singleRay,
                          "Keep -i stageN@ref (one ray at a time) rather than its faster "
                          "wavefront version stageN@fast, which the tasks render by default");
  renderCommand->footer("After --: the scene and the options of pathway render.");

  CLI::App* gradeCommand = cluster->add_subcommand(
      "grade", "Grade a class in --tasks chunks of submissions, then write the class table");
  addSchedulerOptions(*gradeCommand, grade->job);
  gradeCommand->add_option("--submissions", grade->submissions, "A folder of submission folders")
      ->required();
  gradeCommand
      ->add_option("--output", grade->output,
                   "Where each submission's results and the class "
                   "table go")
      ->capture_default_str();
  gradeCommand->footer("After --: options of pathway grade for every submission.");

  return {cluster, [render, grade, renderCommand] {
            // Everything after -- goes to pathway render / pathway grade as it is.
            if (renderCommand->parsed()) {
              render->renderArguments = passedOnArguments();
              return runClusterRender(*render);
            }
            grade->gradeArguments = passedOnArguments();
            return runClusterGrade(*grade);
          }};
}

}  // namespace pathway
