// A student's submission: a folder holding the stage files (a copy of assignments/, or just the
// files, in any sub-folders), built on its own into a stage library (stage_loading/stage_library.h)
// against this build of the framework, in a build folder of its own.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/sandbox.h"
#include "core/temporary_folder.h"

namespace pathway {

struct Submission {
  std::string name;  // the folder's name
  std::string folder;
  std::map<int, std::string> files;     // stage -> its file, for the stages found
  std::vector<std::string> missing;     // stage files not found ("stage3_ao_4d.cpp")
  std::vector<std::string> ignored;     // other source files, not compiled
  std::vector<std::string> duplicates;  // a stage file found more than once (the first is used)
};

// Looks for the five stage files by name. Throws PathwayError when `folder` is not a folder.
Submission findSubmission(const std::string& folder);

// One stage file built into its own stage library, so that a file that does not compile costs
// its own stage only.
struct StageBuild {
  bool succeeded = false;
  std::string library;  // stageN.so in the build's staging folder, when it built
  std::string log;      // the compiler's output (the end of it)
  std::string problem;  // why it did not build, in one line
};

struct SubmissionBuild {
  std::map<int, StageBuild> stages;  // for every stage file found
  double seconds = 0.0;
  std::string sandbox;  // how the compiler was shut in (SandboxState::summary)
  // Where the compiler read and wrote: the libraries live here as long as the build does.
  std::shared_ptr<const TemporaryFolder> staging;
};

// Compiles each of the submission's stage files into a library, stopping the compiler after
// `timeLimit` seconds per file; its messages go to `buildFolder`/stageN-build.log. The compiler
// runs in the sandbox (`sandbox`), as nobody under a root grader, so it works on copies the
// grader stages where that user can read them, wherever the checkout, the class and the output
// are (a clone in /root, an output under a 0700 folder): the framework's headers, and the
// sources and headers beside each stage file (regular files only, no links). It reads those and
// the system, and writes the staging folder's build/. Throws PathwayError when `sandbox` is
// Require and this machine cannot shut it in.
SubmissionBuild buildSubmission(const Submission& submission, const std::string& buildFolder,
                                double timeLimit, SandboxMode sandbox);

}  // namespace pathway
