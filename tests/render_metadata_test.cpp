// A render's metadata goes into an EXR header and comes back field for field; a value that is
// not what its key holds is refused with the file and the key named; merging and grading compare
// the settings they must.
#include "io/render_metadata.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "core/error.h"
#include "io/image_io.h"

namespace pathway {
namespace {

namespace fs = std::filesystem;

RenderMetadata everyField() {
  RenderMetadata m;
  m.scene = "scenes/cornell_box.gltf";
  m.sceneHash = "0123456789abcdef";
  m.integrator = "stage5@ref";
  m.stage = 5;
  m.params = "max-depth=5 rr-depth=3 nee=on light-pick=power";
  m.earlierStages = "reference";
  m.sampler = SamplerType::Stratified;
  m.seed = 12345678901234ull;
  m.filter = FilterType::MitchellNetravali;
  m.filterRadius = 2.0f;
  m.camera =
      CameraRecord{Vec3(1.0f, 2.0f, 3.0f), Vec3(0.0f, 0.5f, -1.0f), Vec3(0.0f, 1.0f, 0.0f), 0.75f};
  m.spp = 24;
  m.sampleBegin = 8;
  m.sampleEnd = 32;
  m.samplesOfWhole = 64;
  m.mergedParts = 3;
  m.primaryRays = 1ull << 40;
  m.secondaryRays = 7;
  m.shadowRays = 9;
  m.samples = 11;
  m.invalidSamples = 2;
  m.unresolvedPixels = 4;
  m.timing = RenderTiming{1.5, 2.5e6};
  m.todos = 2;
  m.todoSites = {"assignments/stage5/stage5_path_tracing.cpp:40", "a.cpp:7"};
  m.grading = GradingRecord{"stage5-cornell-box", 64, 8, 16, {1.25, 1.5, 1.75}, 0.25, 3e6};
  return m;
}

TEST(RenderMetadata, EveryFieldComesBackFromAnExrHeader) {
  const fs::path folder = fs::temp_directory_path() / "pathway_render_metadata_test";
  fs::create_directories(folder);
  const std::string path = (folder / "a.exr").string();
  FilmImages images{Image(2, 2), Image(2, 2), Image(2, 2), {}};
  const RenderMetadata w = everyField();
  writeExr(path, images, w);
  const RenderMetadata r = readImageFile(path).metadata;
  EXPECT_EQ(r.scene, w.scene);
  EXPECT_EQ(r.sceneHash, w.sceneHash);
  EXPECT_EQ(r.integrator, w.integrator);
  EXPECT_EQ(r.stage, w.stage);
  EXPECT_EQ(r.params, w.params);
  EXPECT_EQ(r.earlierStages, w.earlierStages);
  EXPECT_EQ(r.sampler, w.sampler);
  EXPECT_EQ(r.seed, w.seed);
  EXPECT_EQ(r.filter, w.filter);
  EXPECT_EQ(r.filterRadius, w.filterRadius);
  ASSERT_TRUE(r.camera);
  EXPECT_EQ(r.camera->position, w.camera->position);
  EXPECT_EQ(r.camera->lookAt, w.camera->lookAt);
  EXPECT_EQ(r.camera->up, w.camera->up);
  EXPECT_EQ(r.camera->yfov, w.camera->yfov);
  EXPECT_EQ(r.spp, w.spp);
  EXPECT_EQ(r.sampleBegin, w.sampleBegin);
  EXPECT_EQ(r.sampleEnd, w.sampleEnd);
  EXPECT_EQ(r.samplesOfWhole, w.samplesOfWhole);
  EXPECT_EQ(r.mergedParts, w.mergedParts);
  EXPECT_EQ(r.primaryRays, w.primaryRays);
  EXPECT_EQ(r.secondaryRays, w.secondaryRays);
  EXPECT_EQ(r.shadowRays, w.shadowRays);
  EXPECT_EQ(r.samples, w.samples);
  EXPECT_EQ(r.invalidSamples, w.invalidSamples);
  EXPECT_EQ(r.unresolvedPixels, w.unresolvedPixels);
  ASSERT_TRUE(r.timing);
  EXPECT_EQ(r.timing->seconds, w.timing->seconds);
  EXPECT_EQ(r.timing->raysPerSecond, w.timing->raysPerSecond);
  EXPECT_EQ(r.todos, w.todos);
  EXPECT_EQ(r.todoSites, w.todoSites);
  ASSERT_TRUE(r.grading);
  EXPECT_EQ(r.grading->caseId, w.grading->caseId);
  EXPECT_EQ(r.grading->replicates, w.grading->replicates);
  EXPECT_EQ(r.grading->tileSize, w.grading->tileSize);
  EXPECT_EQ(r.grading->blockSize, w.grading->blockSize);
  EXPECT_EQ(r.grading->blockCorrelation, w.grading->blockCorrelation);
  EXPECT_EQ(r.grading->secondsPerRender, w.grading->secondsPerRender);
  EXPECT_EQ(r.grading->raysPerSecond, w.grading->raysPerSecond);

  // A file without metadata reads as nothing known.
  writeExr(path, images, {});
  const RenderMetadata none = readImageFile(path).metadata;
  EXPECT_FALSE(none.seed || none.sampler || none.filter || none.camera || none.timing ||
               none.grading);
  EXPECT_TRUE(none.integrator.empty());
  fs::remove_all(folder);
}

TEST(RenderMetadata, AMalformedValueIsRefusedNamingTheFileAndKey) {
  const std::vector<std::pair<std::string, std::string>> cases[] = {
      {{"pathway:spp", "sixteen"}},
      {{"pathway:seed", "12x"}},
      {{"pathway:filter", "lanczos"}},
      {{"pathway:sampler", "halton"}},
      {{"pathway:sampleRange", "8:4"}, {"pathway:sampleRangeOf", "16"}},
      {{"pathway:sampleRange", "0:32"}, {"pathway:sampleRangeOf", "16"}},
      {{"pathway:cameraPosition", "1 2"}},
      {{"pathway:grading:blockCorrelation", "1 1"},
       {"pathway:grading:case", "x"},
       {"pathway:grading:replicates", "64"},
       {"pathway:grading:tileSize", "8"},
       {"pathway:grading:blockSize", "8"}},
  };
  for (const auto& attributes : cases) {
    try {
      readMetadataAttributes(attributes, "odd.exr");
      ADD_FAILURE() << attributes.front().first << " was accepted";
    } catch (const PathwayError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.rfind("odd.exr: " + attributes.front().first, 0), 0u) << message;
    }
  }
  // A grading reference must carry every number of its record.
  try {
    readMetadataAttributes({{"pathway:grading:case", "x"},
                            {"pathway:grading:blockCorrelation", "1 1 1"},
                            {"pathway:grading:replicates", "64"},
                            {"pathway:grading:tileSize", "8"},
                            {"pathway:grading:blockSize", "8"},
                            {"pathway:grading:raysPerSecond", "1e6"}},
                           "odd.exr");
    ADD_FAILURE() << "a grading record without secondsPerRender was accepted";
  } catch (const PathwayError& error) {
    EXPECT_EQ(std::string(error.what()), "odd.exr: pathway:grading:secondsPerRender '' is missing");
  }
  // Other attributes (another program's) are not Pathway's to judge.
  EXPECT_NO_THROW(readMetadataAttributes({{"owner", "x"}, {"spp", "many"}}, "odd.exr"));
}

TEST(RenderMetadata, PartsMustAgreeOnSettingsAndGradingOnTheExpectedImage) {
  const RenderMetadata first = everyField();
  RenderMetadata part = first;
  part.scene = "/elsewhere/cornell_box.gltf";  // another machine's path: the hash decides
  part.sampleBegin = 32;
  part.sampleEnd = 64;
  part.primaryRays = 5;
  part.timing.reset();
  EXPECT_EQ(partMismatch(part, first), "");
  part.seed = 1;
  EXPECT_EQ(partMismatch(part, first), "seed '1' where the first part has '12345678901234'");

  RenderMetadata student = first;
  student.integrator = "stage5";  // the same stage in the other variant
  student.seed = 99;
  student.earlierStages = "own";
  EXPECT_EQ(expectedImageMismatch(student, first), "");
  student.spp = 48;
  EXPECT_EQ(expectedImageMismatch(student, first), "spp: '48' here, '24' in the reference");
  EXPECT_EQ(expectedImageMismatch(student, first, true), "");
  student.filter = FilterType::Box;
  EXPECT_EQ(expectedImageMismatch(student, first, true),
            "filter: 'box' here, 'mitchell' in the reference");
}

}  // namespace
}  // namespace pathway
