#include "grade/submission.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "core/child_process.h"
#include "core/error.h"
#include "core/regular_file_copy.h"
#include "core/sandboxed_command.h"
#include "stage_loading/stage_library.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

bool isSource(const fs::path& path) {
  const std::string ext = path.extension().string();
  return ext == ".cpp" || ext == ".cc" || ext == ".cxx" || ext == ".c";
}

}  // namespace

Submission findSubmission(const std::string& folder) {
  if (!fs::is_directory(folder)) throw PathwayError(folder + ": not a folder");
  Submission submission;
  submission.folder = fs::absolute(folder).lexically_normal().string();
  submission.name = fs::path(submission.folder).filename().string();
  std::map<std::string, int> stageOfFile;
  for (int stage = 1; stage <= kStageCount; ++stage) stageOfFile[stageInfo(stage).file] = stage;
  std::vector<fs::path> paths;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) paths.push_back(entry.path());
  std::sort(paths.begin(), paths.end());  // the same choice on every machine
  for (const fs::path& path : paths) {
    const auto stage = stageOfFile.find(path.filename().string());
    const std::string relative = fs::relative(path, folder).string();
    if (stage == stageOfFile.end()) {
      if (isSource(path)) submission.ignored.push_back(relative);
    } else if (submission.files.count(stage->second)) {
      submission.duplicates.push_back(relative);
    } else {
      submission.files[stage->second] = path.string();
    }
  }
  for (int stage = 1; stage <= kStageCount; ++stage)
    if (!submission.files.count(stage)) submission.missing.push_back(stageInfo(stage).file);
  return submission;
}

namespace {

std::string withoutPrefixes(std::string text, const std::vector<std::string>& prefixes) {
  for (const std::string& prefix : prefixes) {
    if (prefix.size() <= 1) continue;
    for (size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
      text.erase(at, prefix.size());
  }
  return text;
}

// A compiler's limits: a stage file needs far less than 4 GiB to compile, and its library far
// less than 64 MiB.
constexpr uint64_t kCompilerAddressSpaceBytes = 4ull << 30;
constexpr uint64_t kCompilerFileBytes = 64ull << 20;

// The compile of one stage file, run by this program inside the sandbox: it may read the folders
// the command includes from (the framework's), the file's own folder, and write `buildFolder`.
SandboxedCommand sandboxedCompile(const std::vector<std::string>& compile,
                                  const std::string& buildFolder, double timeLimit,
                                  SandboxMode mode) {
  SandboxedCommand sandboxed;
  sandboxed.mode = mode;
  sandboxed.policy.startsPrograms = true;
  for (const std::string& word : compile)
    if (word.rfind("-I", 0) == 0 && word.size() > 2)
      sandboxed.policy.readable.push_back(word.substr(2));
  sandboxed.policy.writable = {buildFolder};
  sandboxed.policy.addressSpaceBytes = kCompilerAddressSpaceBytes;
  sandboxed.policy.cpuSeconds = static_cast<uint64_t>(std::ceil(timeLimit)) + 1;
  sandboxed.policy.fileBytes = kCompilerFileBytes;
  sandboxed.program = compile;
  return sandboxed;
}

// What a stage file may bring along from its folder and the folders below it: its own headers
// and sources, no larger than any such file is, and not too many.
bool isStagedAlong(const fs::path& path) {
  static const std::vector<std::string> kinds = {".h",   ".hpp", ".hh", ".hxx", ".inl",
                                                 ".ipp", ".cpp", ".cc", ".cxx", ".c"};
  return std::find(kinds.begin(), kinds.end(), path.extension().string()) != kinds.end();
}
constexpr uintmax_t kStagedFileBytes = 1u << 20;
constexpr size_t kStagedFiles = 200;

// A folder's headers (every file named *.h below it), copied to `to`.
void copyHeaders(const fs::path& from, const fs::path& to) {
  for (const auto& entry : fs::recursive_directory_iterator(from))
    if (entry.path().extension() == ".h")
      copyRegularFile(entry.path(), to / fs::relative(entry.path(), from), kStagedFileBytes);
}

// Every folder below `root` searchable and readable by all (the files are already readable).
void openToAll(const fs::path& root) {
  const fs::perms open = fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                         fs::perms::others_read | fs::perms::others_exec;
  fs::permissions(root, open);
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.is_directory()) fs::permissions(entry.path(), open);
}

}  // namespace

SubmissionBuild buildSubmission(const Submission& submission, const std::string& buildFolder,
                                double timeLimit, SandboxMode sandbox) {
  SubmissionBuild build;
  fs::create_directories(buildFolder);
  // The staging folder: the compiler's inputs, copied where the sandbox's user can read them,
  // and the folder it builds in, its own.
  build.staging = std::make_shared<TemporaryFolder>("pathway-build", sandboxTemporaryRoot());
  const fs::path stage = build.staging->path();
  const fs::path sources = stage / "submission";
  const fs::path built = stage / "build";
  std::vector<std::string> compileCommand = stageLibraryCompileCommand();
  std::vector<std::string> stagedPrefixes = {sources.string() + "/", built.string() + "/"};
  for (std::string& word : compileCommand)
    if (word.rfind("-I", 0) == 0 && word.size() > 2 && word.rfind("-I/usr/", 0) != 0) {
      // An include folder of the framework's ("framework"): its headers, under the same name
      // (the system's, under /usr, every user reads as they are).
      const fs::path from = word.substr(2);
      const fs::path to = stage / from.filename();
      copyHeaders(from, to);
      word = "-I" + to.string();
      stagedPrefixes.push_back(stage.string() + "/");
    }
  for (const auto& [stageNumber, file] : submission.files) {
    const fs::path folder = fs::path(file).parent_path();
    const fs::path to = sources / fs::relative(folder, submission.folder);
    std::error_code error;
    // The stage file whatever its size (the compiler's limits hold it); the headers and sources
    // beside it and in folders below it (not through links) if small.
    if (!copyRegularFile(file, to / fs::path(file).filename()))
      build.stages[stageNumber].problem =
          fs::path(file).filename().string() +
          " did not compile: it is no regular file (a symbolic link is not followed)";
    size_t along = 0;
    for (fs::recursive_directory_iterator it(folder, error), end; !error && it != end;
         it.increment(error))
      if (it->is_regular_file() && it->path() != fs::path(file) && isStagedAlong(it->path()) &&
          ++along <= kStagedFiles)
        copyRegularFile(it->path(), to / fs::relative(it->path(), folder), kStagedFileBytes);
  }
  fs::create_directories(sources);
  openToAll(sources);
  for (const auto& entry : fs::directory_iterator(stage))
    if (entry.is_directory() && entry.path() != sources) openToAll(entry.path());
  fs::create_directories(built);
  // Others may pass through the staging folder, not list it; the build folder is the compiler's.
  fs::permissions(stage, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  shareWithSandboxUser(built.string(), sandbox);
  // What every compile reads: the framework and the submission.
  std::vector<std::string> probeCommand = compileCommand;
  probeCommand.push_back("-I" + sources.string());
  build.sandbox =
      "compiler: " +
      probeSandbox(sandboxedCompile(probeCommand, built.string(), timeLimit, sandbox).policy,
                   sandbox)
          .summary();
  const ChildOptions options = untrustedChildOptions(sandbox != SandboxMode::Off);
  for (const auto& [stageNumber, file] : submission.files) {
    StageBuild& result = build.stages[stageNumber];
    if (!result.problem.empty()) continue;  // not staged
    const std::string name = "stage" + std::to_string(stageNumber);
    result.library = (built / (name + ".so")).string();
    const fs::path staged = sources / fs::relative(file, submission.folder);
    std::vector<std::string> compile = compileCommand;
    // A stage file may include a header of its own beside it.
    compile.push_back("-I" + staged.parent_path().string());
    // Its TODOs name the file where the student has it, not the staged copy.
    compile.push_back("-fmacro-prefix-map=" + sources.string() + "=" + submission.folder);
    compile.push_back(staged.string());
    compile.push_back("-o");
    compile.push_back(result.library);
    std::vector<std::string> command = compile;
    if (sandbox != SandboxMode::Off) {
      command = {currentExecutable()};
      for (const std::string& word :
           sandboxedCompile(compile, built.string(), timeLimit, sandbox).toArguments())
        command.push_back(word);
    }
    const ChildOutcome outcome =
        runChild(command, timeLimit, buildFolder + "/" + name + "-build.log", options);
    build.seconds += outcome.seconds;
    // Paths on the grading machine mean nothing to the student: the compiler's message names
    // files by their names in the submission and the framework.
    result.log = withoutPrefixes(outcome.output, stagedPrefixes);
    result.succeeded = outcome.succeeded() && fs::exists(result.library);
    if (!result.succeeded)
      result.problem = fs::path(file).filename().string() + " did not compile: the compiler " +
                       outcome.describe(timeLimit);
  }
  return build;
}

}  // namespace pathway
