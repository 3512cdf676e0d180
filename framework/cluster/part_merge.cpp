#include "cluster/part_merge.h"

#include <algorithm>

#include "core/error.h"
#include "io/partial_film.h"

namespace pathway {
namespace {

std::string range(uint32_t begin, uint32_t end) {
  return std::to_string(begin) + ":" + std::to_string(end);
}

}  // namespace

MergedRender mergeParts(const std::vector<std::string>& paths, bool allowIncomplete) {
  if (paths.empty()) throw PathwayError("merge: no parts given");
  struct Loaded {
    std::string path;
    PartialFilm part;
  };
  // First every header (quick), so a bad part is refused before any sums are read; then the
  // sums one part at a time, so memory holds two films whatever the number of parts.
  std::vector<Loaded> parts;
  for (const std::string& path : paths) parts.push_back({path, readPartialFilm(path, false)});

  const Loaded& first = parts.front();
  for (const Loaded& p : parts) {
    if (p.part.width != first.part.width || p.part.height != first.part.height)
      throw PathwayError(p.path + ": " + std::to_string(p.part.width) + "x" +
                         std::to_string(p.part.height) + " pixels, but " + first.path + " has " +
                         std::to_string(first.part.width) + "x" +
                         std::to_string(first.part.height));
    if (p.part.metadata.samplesOfWhole != first.part.metadata.samplesOfWhole)
      throw PathwayError(p.path + ": a part of a render of " +
                         std::to_string(p.part.metadata.samplesOfWhole) + " spp, but " +
                         first.path + " is a part of one of " +
                         std::to_string(first.part.metadata.samplesOfWhole));
    const std::string mismatch = partMismatch(p.part.metadata, first.part.metadata);
    if (!mismatch.empty())
      throw PathwayError(p.path + ": not a part of the same render as " + first.path + ": " +
                         mismatch);
  }

  std::sort(parts.begin(), parts.end(), [](const Loaded& a, const Loaded& b) {
    return a.part.metadata.sampleBegin < b.part.metadata.sampleBegin;
  });
  for (size_t i = 1; i < parts.size(); ++i) {
    const RenderMetadata& before = parts[i - 1].part.metadata;
    const RenderMetadata& next = parts[i].part.metadata;
    if (next.sampleBegin < before.sampleEnd)
      throw PathwayError(parts[i - 1].path + " (samples " +
                         range(before.sampleBegin, before.sampleEnd) + ") and " + parts[i].path +
                         " (samples " + range(next.sampleBegin, next.sampleEnd) + ") overlap");
    if (next.sampleBegin > before.sampleEnd)
      throw PathwayError("samples " + range(before.sampleEnd, next.sampleBegin) +
                         " are missing: no part between " + parts[i - 1].path + " and " +
                         parts[i].path);
  }
  // The settings as the parts have them; the counters summed; the range the union.
  MergedRender merged;
  RenderMetadata& m = merged.metadata;
  m = first.part.metadata;
  m.sampleBegin = parts.front().part.metadata.sampleBegin;
  m.sampleEnd = parts.back().part.metadata.sampleEnd;
  if (!allowIncomplete && (m.sampleBegin != 0 || m.sampleEnd != m.samplesOfWhole))
    throw PathwayError(
        "the parts cover samples " + range(m.sampleBegin, m.sampleEnd) + " of the render's " +
        range(0, m.samplesOfWhole) + ": samples " +
        (m.sampleBegin != 0 ? range(0, m.sampleBegin) : range(m.sampleEnd, m.samplesOfWhole)) +
        " are missing (or merge with --allow-incomplete)");

  merged.film = Film(first.part.width, first.part.height);
  for (const Loaded& p : parts) {
    const PartialFilm part = readPartialFilm(p.path);
    if (part.width != first.part.width || part.height != first.part.height)
      throw PathwayError(p.path + ": changed while it was being merged");
    merged.film += part.film;
  }
  merged.film.developAll(merged.images.color, merged.images.variance, merged.images.weight,
                         &merged.unresolvedPixels);

  m.spp = m.sampleEnd - m.sampleBegin;
  m.unresolvedPixels = merged.unresolvedPixels;
  m.primaryRays = m.secondaryRays = m.shadowRays = m.samples = m.invalidSamples = 0;
  double seconds = 0.0;
  m.todos = 0;
  m.todoSites.clear();
  for (const Loaded& p : parts) {
    const RenderMetadata& part = p.part.metadata;
    m.primaryRays += part.primaryRays;
    m.secondaryRays += part.secondaryRays;
    m.shadowRays += part.shadowRays;
    m.samples += part.samples;
    m.invalidSamples += part.invalidSamples;
    if (part.timing) seconds += part.timing->seconds;
    if (part.todos > m.todos) {  // the part that ran the most unfinished code speaks for all
      m.todos = part.todos;
      m.todoSites = part.todoSites;
    }
  }
  m.timing = RenderTiming{seconds, seconds > 0 ? double(m.totalRays()) / seconds : 0.0};
  m.mergedParts = static_cast<int>(parts.size());
  return merged;
}

}  // namespace pathway
