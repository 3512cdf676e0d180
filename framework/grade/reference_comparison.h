// The one place a render meets its reference: the grader's cases, `pathway grade --image A
// --reference B` and the viewer's G key all compare through compareWithReference, so a check
// added here (settings that must agree, dropped samples, the filter's negative lobes) holds for
// all three.
#pragma once

#include "grade/grading_reference.h"
#include "grade/image_comparison.h"
#include "io/image_io.h"

namespace pathway {

// What a render is compared with: a grading reference (the variance of a tile's mean from its
// replicates), or one render with its own per-pixel variance (summed over a tile, scaled by how
// much the filter correlates neighbouring pixels).
class ComparisonReference {
 public:
  ComparisonReference(const GradingReference& reference)  // NOLINT: either kind reads the same
      : grading_(&reference), image_(&reference.mean), metadata_(&reference.metadata) {}
  ComparisonReference(const FilmImages& render, const RenderMetadata& metadata)  // NOLINT
      : image_(&render.color), variance_(&render.variance), metadata_(&metadata) {}

 private:
  friend Comparison compareWithReference(const FilmImages&, const RenderMetadata&,
                                         const ComparisonReference&, const ComparisonSettings&);
  const GradingReference* grading_ = nullptr;
  const Image* image_ = nullptr;
  const Image* variance_ = nullptr;
  const RenderMetadata* metadata_ = nullptr;
};

// Throws PathwayError when the two were made with settings that change the expected image or
// its noise (a plain render may have other spp), or when neither carries a variance.
Comparison compareWithReference(const FilmImages& render, const RenderMetadata& metadata,
                                const ComparisonReference& reference,
                                const ComparisonSettings& settings);

}  // namespace pathway
