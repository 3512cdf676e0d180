// `pathway grade --image mine.exr --reference ref.exr`: two files, reported like a stage.
#include "app/grade_modes.h"
#include "core/error.h"
#include "grade/file_comparison.h"

namespace pathway {

int compareFilesMode(const GradeOptions& options) {
  if (options.image.empty() || options.reference.empty())
    throw PathwayError("--image and --reference go together");
  const ComparisonSettings settings;
  return writeGradeSummary(compareImageFiles(options.image, options.reference, settings), options,
                           settings);
}

}  // namespace pathway
