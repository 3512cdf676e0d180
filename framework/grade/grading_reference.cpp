#include "grade/grading_reference.h"

#include <cstdio>
#include <cstdlib>

#include "core/error.h"
#include "grade/difference_diagnosis.h"
#include "grade/difference_patterns.h"
#include "io/image_io.h"

namespace pathway {
namespace {

// What must be equal for two renders to estimate the same image. The integrator is compared by
// stage ("stage3" and "stage3@ref" are the same stage), the seed and counters never.
const char* const kSettingsKeys[] = {"pathway:sceneHash",   "pathway:stage",   "pathway:params",
                                     "pathway:spp",         "pathway:sampler", "pathway:filter",
                                     "pathway:filterRadius"};

std::map<std::string, std::string> toMap(const ImageMetadata& metadata) {
  return std::map<std::string, std::string>(metadata.begin(), metadata.end());
}

}  // namespace

GradingReference makeGradingReference(const GradingCase& gradingCase, const RayTracer& tracer,
                                      const std::function<void(int)>& onReplicate) {
  std::vector<Image> replicates;
  Image ownVariance;  // the mean of the replicates' own per-pixel variance estimates
  GradingReference reference;
  double seconds = 0.0, rays = 0.0;
  for (int i = 0; i < kReferenceReplicates; ++i) {
    const RenderRecipe recipe =
        gradingCase.recipe(Variant::Reference, EarlierStages::Own, kReferenceSeed + i);
    RenderResult result = runRender(tracer, recipe);
    if (result.stats.counters.invalidSamples > 0)
      throw PathwayError(gradingCase.id() + ": the reference dropped " +
                         std::to_string(result.stats.counters.invalidSamples) +
                         " non-finite samples; this case cannot be graded");
    if (i == 0) reference.metadata = toMap(result.metadata);
    seconds += result.stats.seconds;
    rays += static_cast<double>(result.stats.counters.totalRays());
    if (ownVariance.pixels.empty())
      ownVariance = Image(result.images.variance.width, result.images.variance.height);
    for (size_t p = 0; p < ownVariance.pixels.size(); ++p)
      ownVariance.pixels[p] += result.images.variance.pixels[p] / float(kReferenceReplicates);
    replicates.push_back(std::move(result.images.color));
    if (onReplicate) onReplicate(i + 1);
  }
  reference.mean = Image(replicates.front().width, replicates.front().height);
  for (size_t p = 0; p < reference.mean.pixels.size(); ++p) {
    glm::dvec3 sum(0.0);
    for (const Image& replicate : replicates) sum += glm::dvec3(replicate.pixels[p]);
    reference.mean.pixels[p] = Color(sum / double(replicates.size()));
  }
  reference.tileVariance = replicateTileVariance(replicates, gradingCase.tileSize);
  reference.patterns = makeDifferencePatterns(gradingCase, tracer, reference.mean, ownVariance);
  reference.blockSize = ComparisonSettings().omnibusBlockSize;
  reference.blockVariance = replicateTileVariance(replicates, reference.blockSize);
  reference.blockCorrelation = replicateBlockCorrelation(replicates, reference.blockSize);
  reference.replicates = kReferenceReplicates;
  reference.tileSize = gradingCase.tileSize;
  reference.secondsPerRender = seconds / kReferenceReplicates;
  reference.raysPerSecond = seconds > 0.0 ? rays / seconds : 0.0;
  // The replicates' own seed and counters would only mislead; the reference's are these.
  // The replicates' own seed, timing and file path would only mislead (the scene is known by
  // its content hash): the reference's timing is kept in its own keys.
  for (const char* key :
       {"pathway:seed", "pathway:seconds", "pathway:raysPerSecond", "pathway:scene"})
    reference.metadata.erase(key);
  reference.metadata["pathway:grading:case"] = gradingCase.id();
  return reference;
}

void writeGradingReference(const std::string& path, const GradingReference& reference) {
  ImageMetadata metadata(reference.metadata.begin(), reference.metadata.end());
  metadata.push_back({"pathway:grading:replicates", std::to_string(reference.replicates)});
  metadata.push_back({"pathway:grading:tileSize", std::to_string(reference.tileSize)});
  metadata.push_back({"pathway:grading:blockSize", std::to_string(reference.blockSize)});
  char correlation[96];
  std::snprintf(correlation, sizeof correlation, "%.9g %.9g %.9g", reference.blockCorrelation.x,
                reference.blockCorrelation.y, reference.blockCorrelation.z);
  metadata.push_back({"pathway:grading:blockCorrelation", correlation});
  metadata.push_back(
      {"pathway:grading:secondsPerRender", std::to_string(reference.secondsPerRender)});
  metadata.push_back({"pathway:grading:raysPerSecond", std::to_string(reference.raysPerSecond)});
  std::map<std::string, const Image*> layers = {{"", &reference.mean},
                                                {"tileVariance", &reference.tileVariance},
                                                {"blockVariance", &reference.blockVariance}};
  for (const auto& [name, image] : reference.patterns) layers[name] = &image;
  writeExrLayers(path, layers, metadata);
}

GradingReference readGradingReference(const std::string& path) {
  LoadedImage loaded = readImageFile(path);  // names the file when it is missing or broken
  GradingReference reference;
  auto number = [&](const std::string& key) {
    const auto it = loaded.metadata.find(key);
    if (it == loaded.metadata.end())
      throw PathwayError(path + ": not a grading reference (no " + key + ")");
    try {
      return std::stod(it->second);
    } catch (const std::exception&) {
      throw PathwayError(path + ": " + key + " is not a number: '" + it->second + "'");
    }
  };
  reference.replicates = static_cast<int>(number("pathway:grading:replicates"));
  reference.tileSize = static_cast<int>(number("pathway:grading:tileSize"));
  reference.blockSize = static_cast<int>(number("pathway:grading:blockSize"));
  const auto correlation = loaded.metadata.find("pathway:grading:blockCorrelation");
  if (correlation == loaded.metadata.end() ||
      std::sscanf(correlation->second.c_str(), "%lf %lf %lf", &reference.blockCorrelation.x,
                  &reference.blockCorrelation.y, &reference.blockCorrelation.z) != 3)
    throw PathwayError(path + ": not a grading reference (no pathway:grading:blockCorrelation)");
  reference.secondsPerRender = number("pathway:grading:secondsPerRender");
  reference.raysPerSecond = number("pathway:grading:raysPerSecond");
  if (reference.replicates < 2 || reference.tileSize < 1 || reference.blockSize < 1)
    throw PathwayError(path +
                       ": a grading reference needs at least 2 replicates and tiles of 1+ "
                       "pixels");
  for (const char* layer : {"tileVariance", "blockVariance"})
    if (!loaded.layers.count(layer))
      throw PathwayError(path + ": not a grading reference (no " + layer + " layer)");
  reference.mean = std::move(loaded.images.color);
  reference.tileVariance = std::move(loaded.layers["tileVariance"]);
  reference.blockVariance = std::move(loaded.layers["blockVariance"]);
  for (auto& [name, image] : loaded.layers)
    if (name.rfind(pattern::kPrefix, 0) == 0) reference.patterns[name] = std::move(image);
  reference.metadata = std::move(loaded.metadata);
  return reference;
}

double metadataNumber(const std::map<std::string, std::string>& metadata, const std::string& key) {
  const auto it = metadata.find(key);
  return it == metadata.end() ? 0.0 : std::strtod(it->second.c_str(), nullptr);
}

bool negativeValuesAllowed(const std::map<std::string, std::string>& metadata) {
  const auto filter = metadata.find("pathway:filter");
  try {
    return filter != metadata.end() && hasNegativeLobes(parseFilterType(filter->second));
  } catch (const PathwayError&) {
    return false;  // an unknown filter: the strict check
  }
}

Comparison compareWithReference(const FilmImages& render,
                                const std::map<std::string, std::string>& renderMetadata,
                                const GradingReference& reference,
                                const ComparisonSettings& settings) {
  const std::string mismatch = referenceMismatch(renderMetadata, reference.metadata);
  if (!mismatch.empty())
    throw PathwayError("the reference was made with other settings (" + mismatch +
                       "); make the references again or grade with the settings they record");
  ComparisonSettings caseSettings = settings;
  caseSettings.tileSize = reference.tileSize;
  caseSettings.omnibusBlockSize = reference.blockSize;
  ComparisonInput input;
  input.image = &render.color;
  input.reference = &reference.mean;
  input.tileVariance = &reference.tileVariance;
  input.blockVariance = &reference.blockVariance;
  input.blockCorrelation = reference.blockCorrelation;
  input.replicates = reference.replicates;
  if (!render.variance.pixels.empty()) input.imageVariance = &render.variance;
  input.negativeValuesAllowed = negativeValuesAllowed(renderMetadata);
  input.droppedSamples =
      static_cast<uint64_t>(metadataNumber(renderMetadata, "pathway:invalidSamples"));
  return compareImages(input, caseSettings);
}

std::string referenceMismatch(const std::map<std::string, std::string>& render,
                              const std::map<std::string, std::string>& reference) {
  for (const char* key : kSettingsKeys) {
    const auto a = render.find(key), b = reference.find(key);
    // EXR drops empty attributes, so a missing key reads as empty.
    const std::string here = a != render.end() ? a->second : "";
    const std::string there = b != reference.end() ? b->second : "";
    if (here != there)
      return std::string(key).substr(8) + ": '" + here + "' here, '" + there + "' in the reference";
  }
  return "";
}

}  // namespace pathway
