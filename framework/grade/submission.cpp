#include "grade/submission.h"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "core/child_process.h"
#include "core/error.h"
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

}  // namespace

SubmissionBuild buildSubmission(const Submission& submission, const std::string& buildFolder,
                                double timeLimit, SandboxMode sandbox) {
  SubmissionBuild build;
  fs::create_directories(buildFolder);
  const std::string folder = fs::absolute(buildFolder).lexically_normal().string();
  // What every compile reads: the framework and the submission.
  std::vector<std::string> probeCommand = stageLibraryCompileCommand();
  probeCommand.push_back("-I" + submission.folder);
  build.sandbox =
      "compiler: " +
      probeSandbox(sandboxedCompile(probeCommand, folder, timeLimit, sandbox).policy, sandbox)
          .summary();
  // A compiler of a root grader runs as nobody: the build folder is its own.
  shareWithSandboxUser(folder, sandbox);
  for (const auto& [stage, file] : submission.files) {
    StageBuild& result = build.stages[stage];
    const std::string name = "stage" + std::to_string(stage);
    result.library = folder + "/" + name + ".so";
    std::vector<std::string> compile = stageLibraryCompileCommand();
    // A stage file may include a header of its own beside it.
    compile.push_back("-I" + fs::path(file).parent_path().string());
    compile.push_back(file);
    compile.push_back("-o");
    compile.push_back(result.library);
    std::error_code ignored;
    fs::remove(result.library, ignored);
    std::vector<std::string> command = compile;
    if (sandbox != SandboxMode::Off) {
      command = {currentExecutable()};
      for (const std::string& word :
           sandboxedCompile(compile, folder, timeLimit, sandbox).toArguments())
        command.push_back(word);
    }
    const ChildOutcome outcome =
        runChild(command, timeLimit, buildFolder + "/" + name + "-build.log");
    build.seconds += outcome.seconds;
    // Paths on the grading machine mean nothing to the student: the compiler's message names
    // files by their names in the submission and the framework.
    result.log = withoutPrefixes(outcome.output,
                                 {fs::absolute(submission.folder).lexically_normal().string() + "/",
                                  submission.folder + "/", std::string(PATHWAY_SOURCE_DIR) + "/",
                                  fs::absolute(buildFolder).lexically_normal().string() + "/"});
    result.succeeded = outcome.succeeded() && fs::exists(result.library);
    if (!result.succeeded)
      result.problem = fs::path(file).filename().string() + " did not compile: the compiler " +
                       outcome.describe(timeLimit);
  }
  return build;
}

}  // namespace pathway
