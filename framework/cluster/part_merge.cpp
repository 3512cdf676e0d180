#include "cluster/part_merge.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <set>

#include "core/error.h"
#include "io/partial_film.h"

namespace pathway {
namespace {

// Keys that describe one part's run rather than the render: summed or recomputed when merging.
const std::set<std::string> kPerRunKeys = {"pathway:spp",
                                           "pathway:sampleRange",
                                           "pathway:primaryRays",
                                           "pathway:secondaryRays",
                                           "pathway:shadowRays",
                                           "pathway:samples",
                                           "pathway:invalidSamples",
                                           "pathway:unresolvedPixels",
                                           "pathway:seconds",
                                           "pathway:raysPerSecond",
                                           "pathway:todos",
                                           "pathway:todoSites",
                                           "pathway:mergedParts"};
// Not compared: the same scene file may be named by another path on another machine (its
// content's hash, pathway:sceneHash, is compared).
const std::set<std::string> kNotCompared = {"pathway:scene"};
const char* const kSummedCounters[] = {"pathway:primaryRays", "pathway:secondaryRays",
                                       "pathway:shadowRays", "pathway:samples",
                                       "pathway:invalidSamples"};

std::string range(uint32_t begin, uint32_t end) {
  return std::to_string(begin) + ":" + std::to_string(end);
}

double number(const std::map<std::string, std::string>& metadata, const std::string& key) {
  const auto found = metadata.find(key);
  return found == metadata.end() ? 0.0 : std::strtod(found->second.c_str(), nullptr);
}

// The first setting on which `part` differs from `first`, or "".
std::string settingMismatch(const std::map<std::string, std::string>& first,
                            const std::map<std::string, std::string>& part) {
  std::set<std::string> keys;
  for (const auto& entry : first) keys.insert(entry.first);
  for (const auto& entry : part) keys.insert(entry.first);
  for (const std::string& key : keys) {
    if (key.rfind("pathway:", 0) != 0 || kPerRunKeys.count(key) || kNotCompared.count(key))
      continue;
    const auto a = first.find(key), b = part.find(key);
    const std::string here = a != first.end() ? a->second : "(none)";
    const std::string there = b != part.end() ? b->second : "(none)";
    if (here != there)
      return key.substr(8) + " '" + there + "' where the first part has '" + here + "'";
  }
  return "";
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
    if (p.part.whole != first.part.whole)
      throw PathwayError(p.path + ": a part of a render of " + std::to_string(p.part.whole) +
                         " spp, but " + first.path + " is a part of one of " +
                         std::to_string(first.part.whole));
    const std::string mismatch = settingMismatch(first.part.metadata, p.part.metadata);
    if (!mismatch.empty())
      throw PathwayError(p.path + ": not a part of the same render as " + first.path + ": " +
                         mismatch);
  }

  std::sort(parts.begin(), parts.end(),
            [](const Loaded& a, const Loaded& b) { return a.part.begin < b.part.begin; });
  for (size_t i = 1; i < parts.size(); ++i) {
    const PartialFilm& before = parts[i - 1].part;
    const PartialFilm& next = parts[i].part;
    if (next.begin < before.end)
      throw PathwayError(parts[i - 1].path + " (samples " + range(before.begin, before.end) +
                         ") and " + parts[i].path + " (samples " + range(next.begin, next.end) +
                         ") overlap");
    if (next.begin > before.end)
      throw PathwayError("samples " + range(before.end, next.begin) +
                         " are missing: no part between " + parts[i - 1].path + " and " +
                         parts[i].path);
  }
  MergedRender merged;
  merged.begin = parts.front().part.begin;
  merged.end = parts.back().part.end;
  merged.whole = first.part.whole;
  if (!allowIncomplete && (merged.begin != 0 || merged.end != merged.whole))
    throw PathwayError(
        "the parts cover samples " + range(merged.begin, merged.end) + " of the render's " +
        range(0, merged.whole) + ": samples " +
        (merged.begin != 0 ? range(0, merged.begin) : range(merged.end, merged.whole)) +
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

  // The settings as the parts have them; the counters summed; the range the union.
  const std::map<std::string, std::string>& settings = parts.front().part.metadata;
  for (const auto& [key, value] : settings)
    if (!kPerRunKeys.count(key)) merged.metadata.emplace_back(key, value);
  double seconds = 0.0, rays = 0.0, todos = 0.0;
  std::string todoSites;
  for (const char* key : kSummedCounters) {
    unsigned long long total = 0;
    for (const Loaded& p : parts)
      total += std::strtoull(p.part.metadata.count(key) ? p.part.metadata.at(key).c_str() : "0",
                             nullptr, 10);
    merged.metadata.emplace_back(key, std::to_string(total));
    if (std::string(key).find("Rays") != std::string::npos) rays += static_cast<double>(total);
  }
  for (const Loaded& p : parts) {
    seconds += number(p.part.metadata, "pathway:seconds");
    if (number(p.part.metadata, "pathway:todos") > todos) {
      todos = number(p.part.metadata, "pathway:todos");
      todoSites =
          p.part.metadata.count("pathway:todoSites") ? p.part.metadata.at("pathway:todoSites") : "";
    }
  }
  merged.metadata.emplace_back("pathway:spp", std::to_string(merged.end - merged.begin));
  merged.metadata.emplace_back(kSampleRangeKey, range(merged.begin, merged.end));
  merged.metadata.emplace_back("pathway:unresolvedPixels", std::to_string(merged.unresolvedPixels));
  merged.metadata.emplace_back("pathway:seconds", std::to_string(seconds));  // summed over parts
  merged.metadata.emplace_back("pathway:raysPerSecond",
                               std::to_string(seconds > 0 ? rays / seconds : 0.0));
  merged.metadata.emplace_back("pathway:todos", std::to_string(static_cast<int>(todos)));
  merged.metadata.emplace_back("pathway:todoSites", todoSites);
  merged.metadata.emplace_back("pathway:mergedParts", std::to_string(parts.size()));
  return merged;
}

}  // namespace pathway
