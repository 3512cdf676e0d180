// A grading reference: the mean of kReferenceReplicates independent reference renders of one
// grading case at the submission's spp, and the variance of one such render's tile means (and of
// its means over the omnibus tests' larger blocks), stored as an EXR (R, G, B = mean;
// tileVariance.R/G/B; blockVariance.R/G/B; jackknifeVariance.R/G/B; pattern.*.R/G/B) with the
// settings that made it in its metadata.
#pragma once

#include <map>
#include <string>

#include "grade/grading_cases.h"
#include "grade/image_comparison.h"
#include "io/render_metadata.h"
#include "scene/ray_tracer.h"

namespace pathway {

struct GradingReference {
  Image mean;
  Image tileVariance;
  Image blockVariance;  // the same over the omnibus tests' blocks
  // Where a submission's noise counts (GradingCase::ownNoiseCounts): one replicate's own variance
  // of a block mean by the jackknife over its batches, averaged over the replicates; what a
  // submission's jackknife is held against (ComparisonInput::referenceJackknife). Empty in
  // references made before it.
  Image jackknifeVariance;
  // The settings the replicates were made with (no seed, path or timing of their own) ...
  RenderMetadata metadata;
  // ... and how the statistics were made: replicates, tile and block size, the blocks'
  // correlation (see ComparisonInput::blockCorrelation), one replicate's time.
  GradingRecord record;
  // Masks for diagnosing a wrong image (difference_patterns.h), by layer name; references made
  // before them have none.
  std::map<std::string, Image> patterns;
};

// Renders the case's replicates with the reference stage (traced as `tracing` says). Throws
// PathwayError when the reference is not built in or a replicate drops invalid samples.
GradingReference makeGradingReference(const GradingCase& gradingCase, const RayTracer& tracer,
                                      ReferenceTracing tracing = ReferenceTracing::Fastest);

void writeGradingReference(const std::string& path, const GradingReference& reference);
// Throws PathwayError naming the file: missing, unreadable or truncated, or not a grading
// reference (no tileVariance layer or replicate count).
GradingReference readGradingReference(const std::string& path);
// The same from a file already read (`path` names it in messages).
GradingReference gradingReferenceOf(LoadedImage loaded, const std::string& path);

}  // namespace pathway
