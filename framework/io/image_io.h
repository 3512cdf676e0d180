// Image files: EXR through OpenEXR; PNG written through libpng and read through OpenImageIO, in a
// module loaded on first use (io/raster.h).
// EXR keeps everything the grader needs: linear RGB, per-pixel variance and filter weight, and the
// render settings and counters as metadata. PNG is for looking at: exposure, sRGB, 8 bits.
// Files are written to a temporary name and renamed, so a failed write never leaves a broken file.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "film/film.h"
#include "io/raster.h"
#include "io/render_metadata.h"

namespace pathway {

struct FilmImages {
  Image color;
  Image variance;  // of each pixel's estimate
  Image weight;    // Σ w (same in every channel)
  // A grading render developed without each of its sample batches in turn, for its own variance
  // (grade/jackknife_render.h); empty for any other render. Stored as layers jackknife0, ...
  std::vector<Image> jackknife;
};

// Uncompressed (a render's noisy floats barely compress; raster.h).
void writeExr(const std::string& path, const FilmImages& images, const RenderMetadata& metadata);
// An EXR of RGB layers of one size: the layer named "" is R, G, B; a layer "x" is x.R, x.G, x.B.
// ZIP-compressed: the grading references are written this way, and converged images compress.
void writeExrLayers(const std::string& path, const std::map<std::string, const Image*>& layers,
                    const RenderMetadata& metadata);
// `exposure` in stops: pixel values are scaled by 2^exposure before the sRGB curve.
void writePng(const std::string& path, const Image& image, float exposure);
// Picks the format from the extension (.exr or .png); throws PathwayError for anything else.
void writeImageFile(const std::string& path, const FilmImages& images,
                    const RenderMetadata& metadata, float exposure);

// Runs `write` on a temporary name beside `path`, then renames the file into place (or, where this
// process may not remove files, links it there and leaves the temporary); on failure the
// temporary is removed where it can be and the PathwayError names `path`.
void writeThroughTemporary(const std::string& path,
                           const std::function<void(const std::string&)>& write);

// Throws PathwayError unless `path` has a known extension and its folder exists, so a render can
// refuse a bad output path before it starts.
void checkImagePath(const std::string& path);

struct LoadedImage {
  FilmImages images;  // variance and weight are empty when the file has no such channels
  std::map<std::string, Image> layers;  // every other x.R, x.G, x.B triple, by x
  RenderMetadata metadata;
};
// Throws PathwayError naming the file when it cannot be read or its metadata is malformed, or
// (a file the reader does not trust) when it does not fit `limits` (io/raster.h).
LoadedImage readImageFile(const std::string& path, const RasterLimits& limits = {});

// The sRGB transfer curve (linear -> encoded), for values in [0, 1].
float linearToSrgb(float linear);

}  // namespace pathway
