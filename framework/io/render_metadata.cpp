#include "io/render_metadata.h"

#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <sstream>

#include "core/error.h"

namespace pathway {
namespace {

constexpr const char* kPrefix = "pathway:";

// Keys that describe one run rather than the render it belongs to: a merge sums or recomputes
// them, so parts may differ on them.
const std::set<std::string> kPerRunKeys = {
    "spp",     "sampleRange",    "primaryRays",      "secondaryRays", "shadowRays",
    "samples", "invalidSamples", "unresolvedPixels", "seconds",       "raysPerSecond",
    "todos",   "todoSites",      "mergedParts"};
// What two renders of the same expected image with the same noise agree on.
const char* const kExpectedImageKeys[] = {"sceneHash", "stage",  "params",      "spp",
                                          "sampler",   "filter", "filterRadius"};

std::string vec3Text(const Vec3& v) {
  std::ostringstream text;
  text << v.x << " " << v.y << " " << v.z;
  return text.str();
}

std::string joined(const std::vector<std::string>& sites) {
  std::string text;
  for (const std::string& site : sites) text += (text.empty() ? "" : "; ") + site;
  return text;
}

// The attributes without their prefix, in the order they are written.
std::vector<std::pair<std::string, std::string>> keyedText(const RenderMetadata& m) {
  std::vector<std::pair<std::string, std::string>> out;
  auto put = [&](const char* key, const std::string& value) {
    if (!value.empty()) out.emplace_back(key, value);  // EXR keeps no empty attribute
  };
  put("scene", m.scene);
  put("sceneHash", m.sceneHash);
  put("integrator", m.integrator);
  put("stage", std::to_string(m.stage));
  put("params", m.params);
  put("earlierStages", m.earlierStages);
  put("spp", std::to_string(m.spp));
  if (m.samplesOfWhole > 0) {
    put("sampleRange", std::to_string(m.sampleBegin) + ":" + std::to_string(m.sampleEnd));
    put("sampleRangeOf", std::to_string(m.samplesOfWhole));
  }
  if (m.sampler) put("sampler", samplerTypeName(*m.sampler));
  if (m.seed) put("seed", std::to_string(*m.seed));
  if (m.filter) put("filter", filterTypeName(*m.filter));
  put("filterRadius", std::to_string(m.filterRadius));
  put("primaryRays", std::to_string(m.primaryRays));
  put("secondaryRays", std::to_string(m.secondaryRays));
  put("shadowRays", std::to_string(m.shadowRays));
  put("samples", std::to_string(m.samples));
  put("invalidSamples", std::to_string(m.invalidSamples));
  put("unresolvedPixels", std::to_string(m.unresolvedPixels));
  if (m.timing) {
    put("seconds", std::to_string(m.timing->seconds));
    put("raysPerSecond", std::to_string(m.timing->raysPerSecond));
  }
  put("todos", std::to_string(m.todos));
  put("todoSites", joined(m.todoSites));
  if (m.mergedParts > 0) put("mergedParts", std::to_string(m.mergedParts));
  if (m.camera) {
    put("cameraPosition", vec3Text(m.camera->position));
    put("cameraLookAt", vec3Text(m.camera->lookAt));
    put("cameraUp", vec3Text(m.camera->up));
    put("cameraYfov", std::to_string(m.camera->yfov));
  }
  if (const auto& g = m.grading) {
    put("grading:case", g->caseId);
    put("grading:replicates", std::to_string(g->replicates));
    put("grading:tileSize", std::to_string(g->tileSize));
    put("grading:blockSize", std::to_string(g->blockSize));
    char correlation[96];
    std::snprintf(correlation, sizeof correlation, "%.9g %.9g %.9g", g->blockCorrelation.x,
                  g->blockCorrelation.y, g->blockCorrelation.z);
    put("grading:blockCorrelation", correlation);
    if (g->typicalNoise > 0.0) {
      char typical[32];
      std::snprintf(typical, sizeof typical, "%.9g", g->typicalNoise);
      put("grading:typicalNoise", typical);
    }
    put("grading:secondsPerRender", std::to_string(g->secondsPerRender));
    put("grading:raysPerSecond", std::to_string(g->raysPerSecond));
  }
  return out;
}

std::map<std::string, std::string> keyedMap(const RenderMetadata& m) {
  const auto text = keyedText(m);
  return {text.begin(), text.end()};
}

// Reads typed values out of the "pathway:*" attributes, naming the file and key when one is not
// what the key holds.
class AttributeReader {
 public:
  AttributeReader(const std::vector<std::pair<std::string, std::string>>& attributes,
                  const std::string& file)
      : file_(file) {
    for (const auto& [name, value] : attributes)
      if (name.rfind(kPrefix, 0) == 0) values_[name.substr(std::strlen(kPrefix))] = value;
  }

  bool has(const char* key) const { return values_.count(key) > 0; }
  std::string text(const char* key) const {
    const auto found = values_.find(key);
    return found == values_.end() ? "" : found->second;
  }
  template <typename Number>
  Number number(const char* key) const {
    if (!has(key)) return Number{};
    const std::string value = text(key);
    std::istringstream in(value);
    Number parsed{};
    in >> parsed;
    if (in.fail() || !(in >> std::ws).eof()) fail(key, "is not a number");
    return parsed;
  }
  Vec3 vec3(const char* key) const {
    std::istringstream in(text(key));
    Vec3 v(0.0f);
    if (!(in >> v.x >> v.y >> v.z)) fail(key, "is not three numbers");
    return v;
  }
  template <typename Parse>
  auto named(const char* key, Parse parse) const -> std::optional<decltype(parse(""))> {
    if (!has(key)) return std::nullopt;
    try {
      return parse(text(key));
    } catch (const PathwayError& error) {
      fail(key, std::string("is not known: ") + error.what());
    }
  }
  // The same, for a key the file must have once it has any of its section.
  template <typename Number>
  Number required(const char* key) const {
    if (!has(key)) fail(key, "is missing");
    return number<Number>(key);
  }
  [[noreturn]] void fail(const char* key, const std::string& what) const {
    throw PathwayError(file_ + ": " + kPrefix + key + " '" + text(key) + "' " + what);
  }

 private:
  std::string file_;
  std::map<std::string, std::string> values_;
};

std::vector<std::string> split(const std::string& sites) {
  std::vector<std::string> out;
  for (size_t start = 0; start < sites.size();) {
    size_t end = sites.find("; ", start);
    if (end == std::string::npos) end = sites.size();
    if (end > start) out.push_back(sites.substr(start, end - start));
    start = end + 2;
  }
  return out;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> metadataAttributes(const RenderMetadata& m) {
  std::vector<std::pair<std::string, std::string>> attributes;
  for (auto& [key, value] : keyedText(m)) attributes.emplace_back(kPrefix + key, value);
  return attributes;
}

RenderMetadata readMetadataAttributes(
    const std::vector<std::pair<std::string, std::string>>& attributes, const std::string& file) {
  const AttributeReader in(attributes, file);
  RenderMetadata m;
  m.scene = in.text("scene");
  m.sceneHash = in.text("sceneHash");
  m.integrator = in.text("integrator");
  m.stage = in.number<int>("stage");
  m.params = in.text("params");
  m.earlierStages = in.text("earlierStages");
  m.sampler = in.named("sampler", parseSamplerType);
  if (in.has("seed")) m.seed = in.number<uint64_t>("seed");
  m.filter = in.named("filter", parseFilterType);
  m.filterRadius = in.number<float>("filterRadius");
  if (in.has("cameraPosition"))
    m.camera = CameraRecord{in.vec3("cameraPosition"), in.vec3("cameraLookAt"), in.vec3("cameraUp"),
                            in.number<float>("cameraYfov")};
  m.spp = in.number<uint32_t>("spp");
  if (in.has("sampleRange") || in.has("sampleRangeOf")) {
    if (!parseSampleRange(in.text("sampleRange"), m.sampleBegin, m.sampleEnd))
      in.fail("sampleRange", "is not a range A:B of sample indices");
    m.samplesOfWhole = in.number<uint32_t>("sampleRangeOf");
    if (m.sampleEnd > m.samplesOfWhole)
      in.fail("sampleRange",
              "exceeds the render's " + std::to_string(m.samplesOfWhole) + " samples");
  }
  m.mergedParts = in.number<int>("mergedParts");
  m.primaryRays = in.number<uint64_t>("primaryRays");
  m.secondaryRays = in.number<uint64_t>("secondaryRays");
  m.shadowRays = in.number<uint64_t>("shadowRays");
  m.samples = in.number<uint64_t>("samples");
  m.invalidSamples = in.number<uint64_t>("invalidSamples");
  m.unresolvedPixels = in.number<uint64_t>("unresolvedPixels");
  if (in.has("seconds"))
    m.timing = RenderTiming{in.number<double>("seconds"), in.number<double>("raysPerSecond")};
  m.todos = in.number<int>("todos");
  m.todoSites = split(in.text("todoSites"));
  if (in.has("grading:case") || in.has("grading:replicates")) {
    GradingRecord g;
    g.caseId = in.text("grading:case");
    g.replicates = in.required<int>("grading:replicates");
    g.tileSize = in.required<int>("grading:tileSize");
    g.blockSize = in.required<int>("grading:blockSize");
    std::istringstream correlation(in.text("grading:blockCorrelation"));
    if (!(correlation >> g.blockCorrelation.x >> g.blockCorrelation.y >> g.blockCorrelation.z))
      in.fail("grading:blockCorrelation", "is not three numbers");
    g.typicalNoise = in.number<double>("grading:typicalNoise");
    g.secondsPerRender = in.required<double>("grading:secondsPerRender");
    g.raysPerSecond = in.required<double>("grading:raysPerSecond");
    m.grading = g;
  }
  return m;
}

std::string partMismatch(const RenderMetadata& part, const RenderMetadata& first) {
  const auto here = keyedMap(first), there = keyedMap(part);
  std::set<std::string> keys;
  for (const auto& entry : here) keys.insert(entry.first);
  for (const auto& entry : there) keys.insert(entry.first);
  for (const std::string& key : keys) {
    // The scene's path is not compared: its content's hash is.
    if (kPerRunKeys.count(key) || key == "scene") continue;
    const auto a = here.find(key), b = there.find(key);
    const std::string ours = a != here.end() ? a->second : "(none)";
    const std::string theirs = b != there.end() ? b->second : "(none)";
    if (ours != theirs) return key + " '" + theirs + "' where the first part has '" + ours + "'";
  }
  return "";
}

std::string expectedImageMismatch(const RenderMetadata& here, const RenderMetadata& there,
                                  bool ignoreSpp) {
  const auto a = keyedMap(here), b = keyedMap(there);
  for (const std::string key : kExpectedImageKeys) {
    if (ignoreSpp && key == "spp") continue;
    const auto ours = a.find(key), theirs = b.find(key);
    const std::string x = ours != a.end() ? ours->second : "";
    const std::string y = theirs != b.end() ? theirs->second : "";
    if (x != y) return key + ": '" + x + "' here, '" + y + "' in the reference";
  }
  return "";
}

bool parseSampleRange(const std::string& text, uint32_t& begin, uint32_t& end) {
  unsigned long long a = 0, b = 0;
  char extra = 0;
  if (std::sscanf(text.c_str(), "%llu:%llu%c", &a, &b, &extra) != 2 || a >= b || b > 0xffffffffu)
    return false;
  begin = static_cast<uint32_t>(a);
  end = static_cast<uint32_t>(b);
  return true;
}

}  // namespace pathway
