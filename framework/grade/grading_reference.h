// A grading reference: the mean of kReferenceReplicates independent reference renders of one
// grading case at the submission's spp, and the variance of one such render's tile means (and of
// its means over the omnibus tests' larger blocks), stored as an EXR (R, G, B = mean;
// tileVariance.R/G/B; blockVariance.R/G/B; pattern.*.R/G/B) with the settings that made it in its
// metadata.
#pragma once

#include <functional>
#include <map>
#include <string>

#include "grade/grading_cases.h"
#include "grade/image_comparison.h"
#include "scene/ray_tracer.h"

namespace pathway {

struct GradingReference {
  Image mean;
  Image tileVariance;
  Image blockVariance;               // the same over the omnibus tests' blocks
  glm::dvec3 blockCorrelation{1.0};  // see ComparisonInput::blockCorrelation
  int replicates = 0;
  int tileSize = 0;
  int blockSize = 0;
  double secondsPerRender = 0.0;  // of one replicate, the submission's workload
  double raysPerSecond = 0.0;
  std::map<std::string, std::string> metadata;  // "pathway:*"
  // Masks for diagnosing a wrong image (difference_patterns.h), by layer name; references made
  // before them have none.
  std::map<std::string, Image> patterns;
};

// Renders the case's replicates with the reference stage; `onReplicate(done)` reports progress.
// Throws PathwayError when the reference is not built in or a replicate drops invalid samples.
GradingReference makeGradingReference(const GradingCase& gradingCase, const RayTracer& tracer,
                                      const std::function<void(int)>& onReplicate = {});

void writeGradingReference(const std::string& path, const GradingReference& reference);
// Throws PathwayError naming the file: missing, unreadable or truncated, or not a grading
// reference (no tileVariance layer or replicate count).
GradingReference readGradingReference(const std::string& path);

// The settings keys a render and its reference must agree on, and the first disagreement
// ("spp: 16 here, 32 in the reference"), or "" when they agree.
std::string referenceMismatch(const std::map<std::string, std::string>& render,
                              const std::map<std::string, std::string>& reference);

// A number from "pathway:*" metadata; 0 when the key is missing or not a number.
double metadataNumber(const std::map<std::string, std::string>& metadata, const std::string& key);
// Whether the render's filter (its "pathway:filter") can make negative pixels.
bool negativeValuesAllowed(const std::map<std::string, std::string>& metadata);

// Compares one render of a case (its images and "pathway:*" metadata) with the case's reference.
// Throws PathwayError when they were made with other settings.
Comparison compareWithReference(const FilmImages& render,
                                const std::map<std::string, std::string>& renderMetadata,
                                const GradingReference& reference,
                                const ComparisonSettings& settings);

}  // namespace pathway
