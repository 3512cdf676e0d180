// The reference stages compiled into libraries, one per stage (stage_loading/reference_library.h),
// as the grader's child loads them and a handout ships them: sealed for this platform and
// framework, no symbol table, library N registering stage N alone; a library that is missing, cut
// short, corrupt, or made for another platform or framework version is refused with one message
// naming the file and why, and the program works on without them; and in the full repository, the
// libraries render every stage bit for bit as the built-in reference does.
#include "stage_loading/reference_library.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/image_io.h"
#include "render/integrator_registry.h"
#include "run_command.h"
#include "stage_loading/stage_library.h"
#include "stage_under_test.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

const std::string kFolder = PATHWAY_REFERENCE_LIBRARY_DIR;
const std::string kLibrary = kFolder + "/stage5.so";  // the one the seal tests change

void writeFile(const fs::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

// The library's bytes with the line of its seal that starts with `key` replaced.
std::string withSealLine(std::string bytes, const std::string& key, const std::string& line) {
  const size_t at = bytes.rfind("\n" + key + " ");
  EXPECT_NE(at, std::string::npos) << key;
  return bytes.replace(at + 1, bytes.find('\n', at + 1) - at - 1, line);
}

class ReferenceLibrary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder("pathway_reference_library");
    bytes_ = test::readTextFile(kLibrary);
    // A handout whose library is missing works on without it (and says so: the note).
    if (!test::kFullRepository && !referenceStagesProblem().empty())
      GTEST_SKIP() << "reference stages " << loadReferenceStages().describe();
    ASSERT_GT(bytes_.size(), 1000u) << kLibrary << " is missing or empty";
  }
  void TearDown() override { fs::remove_all(dir_); }
  // A copy of the library changed by the test, refused for its reason.
  std::string copy(const std::string& name, const std::string& bytes) {
    const std::string path = (dir_ / name).string();
    writeFile(path, bytes);
    return path;
  }
  // A folder of the five libraries with stage 5's replaced by `bytes`; returns that file's path.
  std::string folderWith(const std::string& name, const std::string& bytes) {
    const fs::path folder = dir_ / name;
    fs::create_directories(folder);
    for (int stage = 1; stage < kStageCount; ++stage) {
      const std::string file = "stage" + std::to_string(stage) + ".so";
      fs::copy_file(kFolder + "/" + file, folder / file);
    }
    writeFile(folder / "stage5.so", bytes);
    return (folder / "stage5.so").string();
  }
  // `pathway <arguments>` run with the libraries in `folder` in place of the usual ones.
  test::CommandOutcome runWith(const std::string& folder, const std::string& arguments) {
    return test::runCommand("PATHWAY_REFERENCE_LIBRARIES='" + folder + "' " + PATHWAY_BINARY + " " +
                            arguments);
  }

  fs::path dir_;
  std::string bytes_;
};

TEST_F(ReferenceLibrary, IsSealedForThisBuildAndHasNoSymbolTable) {
  EXPECT_EQ(referenceLibrariesProblem(), "");
  for (int stage = 1; stage <= kStageCount; ++stage) {
    const std::string library = kFolder + "/stage" + std::to_string(stage) + ".so";
    EXPECT_EQ(referenceLibraryProblem(library), "");
    EXPECT_EQ(test::readTextFile(library).find(".symtab"), std::string::npos)
        << library << ": the symbol table was not stripped";
    const test::CommandOutcome exported = test::runCommand("nm -D --defined-only " + library);
    EXPECT_EQ(exported.exitCode, 0) << exported.output;
    EXPECT_EQ(exported.output, "") << library << " exports symbols of its own";
  }
  // This process found its reference stages where the program finds them.
  const ReferenceStages& stages = loadReferenceStages();
  EXPECT_EQ(stages.source, test::kFullRepository ? ReferenceStages::Source::BuiltIn
                                                 : ReferenceStages::Source::Library)
      << stages.describe();
  EXPECT_EQ(stages.problem, "");
}

TEST_F(ReferenceLibrary, ARefusedLibraryIsNamedWithItsReason) {
  std::string flipped = bytes_;
  flipped[bytes_.size() / 2] ^= 0x10;
  const struct {
    std::string file, reason;
  } refused[] = {
      {(dir_ / "missing.so").string(), "is missing"},
      {copy("truncated.so", bytes_.substr(0, bytes_.size() / 2)), "no seal at its end"},
      {copy("not_a_library.so", "<html>404</html>\n"), "not a sealed Pathway reference library"},
      {copy("appended.so", bytes_ + "more\n"), "is corrupt"},
      {copy("seal_changed.so", withSealLine(bytes_, "crc32", "crc32 00000000")), "is corrupt"},
      {copy("corrupt.so", flipped), "is corrupt"},
      {copy("other_interface.so", withSealLine(bytes_, "interface", "interface 0123456789abcdef")),
       "another version of the framework (stage interface 0123456789abcdef"},
      {copy("other_platform.so",
            withSealLine(bytes_, "platform", "platform ubuntu 24.04 aarch64, GNU 13")),
       "was built for ubuntu 24.04 aarch64, GNU 13, and this program for"},
      {copy("other_layout.so", withSealLine(bytes_, "layout", "layout Vec3 16, Ray 32")),
       "other sizes of the types it shares with the program (Vec3 16, Ray 32; this program: Vec3 "
       "12, "},
  };
  for (const auto& [file, reason] : refused) {
    const std::string problem = referenceLibraryProblem(file);
    EXPECT_NE(problem.find(file), std::string::npos) << problem;
    EXPECT_NE(problem.find(reason), std::string::npos) << problem;
  }
  // A sealed file that is no library passes the seal and is refused by the loader.
  const std::string text = folderWith("sealed_text", "not an ELF file\n");
  sealReferenceLibrary(text);
  EXPECT_EQ(referenceLibraryProblem(text), "");
  const test::CommandOutcome loaded = runWith(fs::path(text).parent_path().string(), "reference");
  EXPECT_NE(loaded.output.find(text + " cannot be loaded"), std::string::npos) << loaded.output;
}

TEST_F(ReferenceLibrary, TheProgramSaysWhatIsOffAndWorksOnWithoutIt) {
  std::string flipped = bytes_;
  flipped[bytes_.size() / 3] ^= 0x01;
  const std::string corrupt = folderWith("corrupt", flipped);
  const std::string folder = fs::path(corrupt).parent_path().string();
  const std::string image = (dir_ / "a.exr").string();
  // Said once, naming the file and why; the student's own stage renders as ever.
  const test::CommandOutcome render =
      runWith(folder, "render -q -i stage1 --spp 1 --width 8 --height 8 -o " + image);
  EXPECT_EQ(render.exitCode, 0) << render.output;
  EXPECT_TRUE(fs::exists(image));
  const std::string note = "pathway: note: reference stages ";
  ASSERT_NE(render.output.find(note), std::string::npos) << render.output;
  EXPECT_EQ(render.output.find(note), render.output.rfind(note)) << "said more than once";
  EXPECT_NE(render.output.find(corrupt + " is corrupt"), std::string::npos) << render.output;

  const test::CommandOutcome status = runWith(folder, "reference");
  EXPECT_NE(status.output.find(corrupt + " is corrupt"), std::string::npos) << status.output;
  if (test::kFullRepository) {  // the built-in reference stays
    EXPECT_EQ(status.exitCode, 0) << status.output;
    EXPECT_NE(status.output.find("built in"), std::string::npos) << status.output;
    return;
  }
  EXPECT_EQ(status.exitCode, 1) << status.output;
  EXPECT_NE(status.output.find("not available"), std::string::npos) << status.output;
  const test::CommandOutcome list = runWith(folder, "render --list");
  EXPECT_EQ(list.exitCode, 0);
  EXPECT_EQ(list.output.find("@ref"), std::string::npos) << list.output;
  const test::CommandOutcome reference = runWith(folder, "render -q -i stage5@ref -o " + image);
  EXPECT_EQ(reference.exitCode, 1);
  EXPECT_NE(reference.output.find("no reference stages: " + corrupt + " is corrupt"),
            std::string::npos)
      << reference.output;
  // The grader grades the stages together, and the report says why.
  const std::string report = (dir_ / "report").string();
  runWith(folder, "grade -q --stage 2 --report " + report);
  const std::string page = test::readTextFile(report + "/index.html");
  EXPECT_NE(page.find("graded together"), std::string::npos);
  EXPECT_NE(page.find("corrupt"), std::string::npos);
}

TEST_F(ReferenceLibrary, RendersEveryStageBitForBitAsTheBuiltInReference) {
  if (!test::kFullRepository) GTEST_SKIP() << "needs the reference built in, to compare with";
  const test::CommandOutcome status = runWith(kFolder, "reference");
  ASSERT_NE(status.output.find("reference stages: from " + kFolder), std::string::npos)
      << status.output;
  // Every reference stage, and a student stage on the reference's earlier stages.
  for (const std::string integrator : {"stage1@ref", "stage2@ref", "stage3@ref", "stage4@ref",
                                       "stage5@ref", "stage3 --earlier-stages reference"}) {
    const std::string arguments = "render -q --width 40 --height 40 --spp 4 --filter mitchell -i " +
                                  integrator + " -o " + (dir_ / "a.exr").string();
    ASSERT_EQ(test::runCommand(std::string(PATHWAY_BINARY) + " " + arguments).exitCode, 0);
    const LoadedImage builtIn = readImageFile((dir_ / "a.exr").string());
    ASSERT_EQ(runWith(kFolder, arguments).exitCode, 0);
    const LoadedImage library = readImageFile((dir_ / "a.exr").string());
    EXPECT_EQ(library.images.color.pixels, builtIn.images.color.pixels) << integrator;
    EXPECT_EQ(library.images.variance.pixels, builtIn.images.variance.pixels) << integrator;
    EXPECT_EQ(library.images.weight.pixels, builtIn.images.weight.pixels) << integrator;
    EXPECT_EQ(library.metadata.shadowRays, builtIn.metadata.shadowRays);
  }
}

// Library N registers reference stage N, and its wavefront version where it has one, and nothing
// else: the code of the earlier stages it carries registers nothing. (In a child process: the
// libraries would replace this test program's built-in stages.)
TEST_F(ReferenceLibrary, EachLibraryRegistersItsOwnStageAlone) {
  for (int stage = 1; stage <= kStageCount; ++stage) {
    // A copy: a handout's test program has loaded the originals already, and loading a file
    // again registers nothing.
    const std::string library =
        copy("stage" + std::to_string(stage) + ".so",
             test::readTextFile(kFolder + "/stage" + std::to_string(stage) + ".so"));
    EXPECT_EXIT(
        {
          const size_t before = registrationLog().size();
          loadReferenceStageLibrary(library, stage);
          const std::vector<std::string>& log = registrationLog();
          for (size_t i = before; i < log.size(); ++i) {
            const IntegratorInfo& info = findIntegrator(log[i]);
            if (info.stage != stage || info.variant != Variant::Reference) {
              std::fprintf(stderr, "%s registered %s\n", library.c_str(), log[i].c_str());
              std::exit(1);
            }
          }
          std::exit(log.size() > before ? 0 : 2);
        },
        ::testing::ExitedWithCode(0), "")
        << library;
  }
}

}  // namespace
}  // namespace pathway
