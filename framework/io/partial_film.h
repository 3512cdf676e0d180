// A part of a render on disk. It is an ordinary EXR render (R, G, B, variance, weight and the
// "pathway:*" metadata, so any tool can open it) that also carries the film's sums bit for bit:
// each double as two 32-bit unsigned channels "film.<sum>.hi/.lo". `pathway merge` adds the sums
// of parts over disjoint sample ranges, which gives the image one render over their union gives.
#pragma once

#include <cstdint>
#include <string>

#include "film/film.h"
#include "io/image_io.h"
#include "io/render_metadata.h"

namespace pathway {

struct PartialFilm {
  Film film{0, 0};
  int width = 0, height = 0;
  // Its sample range: indices [sampleBegin, sampleEnd) of a render of samplesOfWhole spp.
  RenderMetadata metadata;
};

// Written through a temporary file, like every image. Throws PathwayError naming `path`.
void writePartialFilm(const std::string& path, const Film& film, const FilmImages& images,
                      const RenderMetadata& metadata);
// Throws PathwayError naming `path` when it cannot be read (missing, truncated) or is not a part
// (no film sums or no sample range in its metadata). With `withSums` false only the header is
// read (metadata, range and size; the film stays empty), which is quick.
PartialFilm readPartialFilm(const std::string& path, bool withSums = true);

}  // namespace pathway
