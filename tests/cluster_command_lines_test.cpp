// The command lines a cluster job's tasks run (cluster/command_lines.h), word for word: the task
// scripts of `pathway cluster render|grade` are made of them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cluster/command_lines.h"

namespace pathway {
namespace {

using Words = std::vector<std::string>;

TEST(ClusterCommandLines, RenderPartsAndTheirCheck) {
  RenderPartCommand part;
  part.renderArguments = {"scene one.gltf", "-i", "stage5@ref"};
  part.spp = 4096;
  part.sampleBegin = 1024;
  part.sampleEnd = 2048;
  part.threads = 4;
  part.quiet = true;
  part.output = "/work/parts/part-0001.exr";
  EXPECT_EQ(part.toArguments(),
            (Words{"render", "scene one.gltf", "-i", "stage5@ref", "--spp", "4096", "--samples",
                   "1024:2048", "--threads", "4", "-q", "-o", "/work/parts/part-0001.exr"}));
  RenderPartCommand check;
  check.renderArguments = {"scene.gltf"};
  check.spp = 64;
  check.sampleEnd = 64;
  check.checkOnly = true;
  check.output = "/work/parts/check.exr";
  EXPECT_EQ(check.toArguments(), (Words{"render", "scene.gltf", "--spp", "64", "--samples", "0:64",
                                        "--check", "-o", "/work/parts/check.exr"}));
}

TEST(ClusterCommandLines, TheMerge) {
  MergeCommand merge;
  merge.quiet = true;
  merge.exposure = -1.5f;
  merge.parts = {"a.exr", "b.exr"};
  merge.outputs = {"/out/ref.exr", "/out/ref.png"};
  EXPECT_EQ(merge.toArguments(), (Words{"merge", "-q", "--exposure", "-1.500000", "a.exr", "b.exr",
                                        "-o", "/out/ref.exr", "-o", "/out/ref.png"}));
}

TEST(ClusterCommandLines, GradingAClass) {
  GradeOptionsCheckCommand check;
  check.gradeArguments = {"--time-limit", "60"};
  EXPECT_EQ(check.toArguments(), (Words{"grade", "--list-cases", "--time-limit", "60"}));
  SubmissionGradeCommand submission;
  submission.quiet = true;
  submission.submission = "/class/alice smith";
  submission.output = "/grades/alice smith";
  submission.gradeArguments = {"--stage", "2"};
  EXPECT_EQ(submission.toArguments(), (Words{"grade", "-q", "--submission", "/class/alice smith",
                                             "--output", "/grades/alice smith", "--stage", "2"}));
  ClassTableCommand table;
  table.quiet = true;
  table.submissions = "/class";
  table.output = "/grades";
  EXPECT_EQ(table.toArguments(), (Words{"grade", "-q", "--submissions", "/class", "--output",
                                        "/grades", "--table-only"}));
}

}  // namespace
}  // namespace pathway
