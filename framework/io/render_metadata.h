// What an image file says about how it was made: the settings that decide the image, the samples
// it holds, what they cost, and (for some files) the viewer's camera or a grading reference's
// statistics. It travels as "pathway:<key>" string attributes in the EXR header; this file and
// render_metadata.cpp are the only ones that know the keys and their text.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/math.h"
#include "film/pixel_filter.h"
#include "sampling/sampler.h"

namespace pathway {

// The viewer's camera, saved with an image made in the viewer.
struct CameraRecord {
  Vec3 position{0.0f}, lookAt{0.0f}, up{0.0f};
  float yfov = 0.0f;  // radians
};

// How a grading reference's statistics were made (grade/grading_reference.h).
struct GradingRecord {
  std::string caseId;
  int replicates = 0;
  int tileSize = 0;
  int blockSize = 0;
  glm::dvec3 blockCorrelation{1.0};
  // A replicate's typical noise by the jackknife (grade/image_comparison.h, typicalNoise), the
  // median over the replicates: what a submission's is divided by. 0: not made.
  double typicalNoise = 0.0;
  double secondsPerRender = 0.0;  // of one replicate
  double raysPerSecond = 0.0;
};

struct RenderTiming {
  double seconds = 0.0;
  double raysPerSecond = 0.0;
};

// Fields a file does not carry read as their defaults here (empty, 0, no value).
struct RenderMetadata {
  // What decides the image.
  std::string scene;          // the path it was loaded from (another machine may name it otherwise)
  std::string sceneHash;      // of the scene's content
  std::string integrator;     // "stage3" or "stage3@ref"
  int stage = 0;              // 0: not a course stage
  std::string params;         // every parameter: "name=value name=value"
  std::string earlierStages;  // "own" or "reference"
  std::optional<SamplerType> sampler;
  std::optional<uint64_t> seed;  // none in a grading reference (a mean over seeds)
  std::optional<FilterType> filter;
  float filterRadius = 0.0f;           // pixels
  std::optional<CameraRecord> camera;  // an image saved from the viewer
  // The samples it holds: indices [sampleBegin, sampleEnd) of a render of samplesOfWhole spp.
  uint32_t spp = 0;
  uint32_t sampleBegin = 0, sampleEnd = 0, samplesOfWhole = 0;
  int mergedParts = 0;  // > 0: `pathway merge` added up this many parts
  // What they cost and found.
  uint64_t primaryRays = 0, secondaryRays = 0, shadowRays = 0;
  uint64_t samples = 0, invalidSamples = 0;  // invalid: non-finite, dropped
  uint64_t unresolvedPixels = 0;             // Σw ≈ 0
  std::optional<RenderTiming> timing;        // none in a grading reference (its own is below)
  int todos = 0;                             // unfinished stage code that ran ...
  std::vector<std::string> todoSites;        // ... at these "file:line"s
  std::optional<GradingRecord> grading;      // a grading reference

  uint64_t totalRays() const { return primaryRays + secondaryRays + shadowRays; }
};

// The header attributes, "pathway:<key>" -> text.
std::vector<std::pair<std::string, std::string>> metadataAttributes(const RenderMetadata& metadata);
// From a file's string attributes (others than "pathway:*" are skipped). Throws PathwayError
// naming `file` and the key when a value is not what its key holds (a number, a filter, ...).
RenderMetadata readMetadataAttributes(
    const std::vector<std::pair<std::string, std::string>>& attributes, const std::string& file);

// The first setting on which two files differ, as "name 'here' ... 'there'", or "" when they
// agree. Parts of one render agree on every setting except the scene's path.
std::string partMismatch(const RenderMetadata& part, const RenderMetadata& first);
// What must agree for two renders to estimate the same image with the same noise: the scene's
// content, the stage (not the variant), parameters, sampler, filter and, unless `ignoreSpp`, the
// samples per pixel. The seed and the counters never.
std::string expectedImageMismatch(const RenderMetadata& here, const RenderMetadata& there,
                                  bool ignoreSpp = false);

// "A:B" with A < B < 2^32 into begin and end; false otherwise.
bool parseSampleRange(const std::string& text, uint32_t& begin, uint32_t& end);

}  // namespace pathway
