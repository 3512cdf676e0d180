#include "grade/reference_comparison.h"

#include "core/error.h"

namespace pathway {

Comparison compareWithReference(const FilmImages& render, const RenderMetadata& metadata,
                                const ComparisonReference& reference,
                                const ComparisonSettings& settings) {
  const GradingReference* grading = reference.grading_;
  const std::string mismatch = expectedImageMismatch(metadata, *reference.metadata_, !grading);
  if (!mismatch.empty())
    throw PathwayError(grading ? "the reference was made with other settings (" + mismatch +
                                     "); make the references again or grade with the settings "
                                     "they record"
                               : "the two files were made with other settings (" + mismatch + ")");
  ComparisonSettings used = settings;
  ComparisonInput input;
  input.image = &render.color;
  input.reference = reference.image_;
  if (!render.variance.pixels.empty()) input.imageVariance = &render.variance;
  if (grading) {
    used.tileSize = grading->record.tileSize;
    used.omnibusBlockSize = grading->record.blockSize;
    input.tileVariance = &grading->tileVariance;
    input.blockVariance = &grading->blockVariance;
    input.blockCorrelation = grading->record.blockCorrelation;
    input.replicates = grading->record.replicates;
    if (!render.jackknife.empty()) input.jackknife = &render.jackknife;
    if (!grading->jackknifeVariance.pixels.empty())
      input.referenceJackknife = &grading->jackknifeVariance;
    input.referenceTypicalNoise = grading->record.typicalNoise;
    if (const GradingCase* gradingCase = gradingCaseOrNull(grading->record.caseId)) {
      input.noiseBound = gradingCase->noiseBound;
      input.requiredTechnique = gradingCase->requiredTechnique;
    }
  } else {
    if (!reference.variance_->pixels.empty()) input.referenceVariance = reference.variance_;
    if (!input.imageVariance && !input.referenceVariance)
      throw PathwayError(
          "neither image carries a variance: render both with pathway render to .exr, or "
          "compare with a grading reference");
    // A file without pathway metadata counts as box-filtered (pixels independent).
    input.pixelCorrelation = filterPixelCorrelation(metadata.filter ? metadata.filterRadius : 0.5);
  }
  input.negativeValuesAllowed = metadata.filter && hasNegativeLobes(*metadata.filter);
  input.droppedSamples = metadata.invalidSamples;
  return compareImages(input, used);
}

}  // namespace pathway
