// The `pathway` commands a cluster job runs (app/cluster_command.cpp), one struct each with
// toArguments(): the command line after the program's path. Written here, and only here, so no
// file strings together another command's flags by hand; the settings' flags come from their
// declarations (engine/render_settings.h), as the commands themselves declare them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pathway {

// `pathway render <scene and options> --spp N --samples A:B ...`: one task's part of a render
// split by samples (render --samples), or the check that every task's options pass (--check:
// loads the scene and checks them, renders nothing).
// The render's arguments with a reference stage (-i stageN@ref, -istageN@ref, --integrator
// stageN@ref or --integrator=stageN@ref) replaced by its wavefront version where it has one: the
// same estimator and numbers, traced many paths at a time (`pathway cluster render` without
// --single-ray).
std::vector<std::string> withFastestReference(std::vector<std::string> renderArguments);

struct RenderPartCommand {
  std::vector<std::string> renderArguments;  // the scene and render options, as they were given
  uint32_t spp = 0;                          // of the whole render
  uint32_t sampleBegin = 0, sampleEnd = 0;   // this part's samples
  int threads = 0;                           // 0: left out (the render's default, every core)
  bool checkOnly = false;
  bool quiet = false;
  std::string output;

  std::vector<std::string> toArguments() const;
};

// `pathway merge [-q] --exposure E <parts> -o <output>...`: the parts merged into the image.
struct MergeCommand {
  bool quiet = false;
  float exposure = 0.0f;
  std::vector<std::string> parts;
  std::vector<std::string> outputs;

  std::vector<std::string> toArguments() const;
};

// `pathway grade --list-cases <grade options>`: checks the grade options every submission will be
// graded with, grading nothing.
struct GradeOptionsCheckCommand {
  std::vector<std::string> gradeArguments;  // as they were given

  std::vector<std::string> toArguments() const;
};

// `pathway grade [-q] --submission DIR --output OUT <grade options>`: one submission of a class.
struct SubmissionGradeCommand {
  bool quiet = false;
  std::string submission;
  std::string output;
  std::vector<std::string> gradeArguments;  // as they were given

  std::vector<std::string> toArguments() const;
};

// `pathway grade [-q] --submissions DIR --output OUT --table-only`: the class table from the
// results its submissions' tasks wrote.
struct ClassTableCommand {
  bool quiet = false;
  std::string submissions;
  std::string output;

  std::vector<std::string> toArguments() const;
};

}  // namespace pathway
