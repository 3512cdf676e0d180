// Merging the parts of one render (`pathway merge`): parts rendered over disjoint sample ranges,
// on one machine or as the tasks of a cluster array, add up to the render of their union.
//
// What makes that exact: a sample is a pure function of (pixel, index, dimension, seed), and each
// part stores the film's sums bit for bit (io/partial_film.h), so the merged sums hold the very
// same terms a single render adds, only summed in another order.
#pragma once

#include <string>
#include <vector>

#include "film/film.h"
#include "io/image_io.h"

namespace pathway {

struct MergedRender {
  Film film{0, 0};
  FilmImages images;
  // The parts' settings, their counters summed, their sample ranges' union.
  RenderMetadata metadata;
  size_t unresolvedPixels = 0;
};

// Reads and checks the parts, then adds them in the order of their ranges (so the result does
// not depend on the order of `paths`). Refuses, with a PathwayError naming the files: a part that
// cannot be read or is not a part, parts of other scenes, settings or sizes, overlapping ranges,
// and a gap between ranges (a missing part). Unless `allowIncomplete`, the union must also cover
// the whole render's samples [0, N).
MergedRender mergeParts(const std::vector<std::string>& paths, bool allowIncomplete);

}  // namespace pathway
