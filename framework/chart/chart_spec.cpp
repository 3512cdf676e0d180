#include "chart/chart_spec.h"

#include <set>

#include "core/error.h"
#include "render/parameters.h"

namespace pathway {
namespace {

std::string trim(const std::string& text) {
  const size_t first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

// A number from the whole of `text`, or a PathwayError naming the key and the configuration.
double parseNumber(const std::string& text, const std::string& key, const std::string& source) {
  size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size())
    throw PathwayError("chart configuration \"" + source + "\": " + key + "=" + text +
                       " is not a number");
  return value;
}

// The words of `text`, split at spaces outside double quotes; the quotes are dropped, so that
// reference="4D, Sobol'" is one word.
std::vector<std::string> splitWords(const std::string& text, const std::string& source) {
  std::vector<std::string> words;
  std::string word;
  bool quoted = false, inWord = false;
  for (char c : text) {
    if (c == '"') {
      quoted = !quoted;
      inWord = true;
    } else if ((c == ' ' || c == '\t') && !quoted) {
      if (inWord) words.push_back(word);
      word.clear();
      inWord = false;
    } else {
      word += c;
      inWord = true;
    }
  }
  if (quoted) throw PathwayError("chart configuration \"" + source + "\": a quote is not closed");
  if (inWord) words.push_back(word);
  return words;
}

}  // namespace

bool isPowerOfTwo(uint32_t value) {
  return value != 0 && (value & (value - 1)) == 0;
}

ChartConfig parseChartConfig(const std::string& text) {
  ChartConfig config;
  config.source = text;
  const size_t colon = text.find(": ");
  if (colon == std::string::npos)
    throw PathwayError("chart configuration \"" + text +
                       "\": expected \"LABEL: INTEGRATOR [key=value ...]\"");
  config.label = trim(text.substr(0, colon));
  if (config.label.empty())
    throw PathwayError("chart configuration \"" + text + "\": the label before ':' is empty");
  std::vector<std::string> words = splitWords(text.substr(colon + 2), text);
  if (words.empty())
    throw PathwayError("chart configuration \"" + text + "\": no integrator after the label");
  config.choices.integrator = words.front();
  config.choices.scene.clear();
  for (size_t i = 1; i < words.size(); ++i) {
    const std::string& word = words[i];
    if (word.find('=') == std::string::npos || word.front() == '=')
      throw PathwayError("chart configuration \"" + text + "\": \"" + word + "\" is not key=value");
    const auto [key, value] = splitParamAssignment(word);
    if (key == "sampler")
      config.choices.sampler = value;
    else if (key == "filter")
      config.choices.filter = value;
    else if (key == "filter-radius")
      config.choices.filterRadius = static_cast<float>(parseNumber(value, key, text));
    else if (key == "scene")
      config.choices.scene = value;
    else if (key == "max-spp") {
      const double spp = parseNumber(value, key, text);
      if (!(spp >= 1.0 && spp <= setting::kChartMaxSpp.maxValue) ||
          !isPowerOfTwo(static_cast<uint32_t>(spp)) || spp != double(uint32_t(spp)))
        throw PathwayError("chart configuration \"" + text + "\": max-spp=" + value +
                           " must be a power of two from 1 to " +
                           setting::kChartMaxSpp.format(setting::kChartMaxSpp.maxValue));
      config.maxSpp = static_cast<uint32_t>(spp);
    } else if (key == "reference")
      config.referenceFrom = value;
    else if (key == "group")
      config.group = value;
    else if (key == "x")
      config.x = parseNumber(value, key, text);
    else
      config.choices.params.push_back(word);
  }
  return config;
}

uint32_t ChartSpec::maxSppOf(const ChartConfig& config) const {
  return config.maxSpp ? config.maxSpp : maxSpp;
}

const std::string& ChartSpec::sceneOf(const ChartConfig& config) const {
  return config.choices.scene.empty() ? scene : config.choices.scene;
}

const ChartConfig& ChartSpec::referenceConfigOf(const ChartConfig& config) const {
  if (config.referenceFrom.empty()) return config;
  for (const ChartConfig& other : configs)
    if (other.label == config.referenceFrom) return other;
  throw PathwayError("chart configuration \"" + config.source + "\": reference=" +
                     config.referenceFrom + " names no configuration of this chart");
}

void ChartSpec::check() const {
  if (configs.empty()) throw PathwayError("a chart needs at least one --config");
  if (!setting::kChartWidth.accepts(width) || !setting::kChartMaxSpp.accepts(maxSpp) ||
      !isPowerOfTwo(maxSpp) || !setting::kChartSeeds.accepts(seeds) ||
      !setting::kReferenceFactor.accepts(referenceFactor))
    throw PathwayError("chart settings out of range: width " + std::to_string(width) +
                       ", max-spp " + std::to_string(maxSpp) + " (a power of two), seeds " +
                       std::to_string(seeds) + ", reference-factor " +
                       std::to_string(referenceFactor));
  std::set<std::string> labels;
  for (const ChartConfig& config : configs) {
    if (!labels.insert(config.label).second)
      throw PathwayError("two chart configurations are labelled \"" + config.label + "\"");
    try {
      // Where a configuration's settings enter: refused here, before anything renders.
      config.choices.recipe().settings.check();
    } catch (const PathwayError& error) {
      throw PathwayError("chart configuration \"" + config.source + "\": " + error.what());
    }
    if (sceneOf(config).empty())
      throw PathwayError("chart configuration \"" + config.source +
                         "\": no scene (give the chart a scene or the configuration scene=)");
    const ChartConfig& reference = referenceConfigOf(config);
    if (!reference.referenceFrom.empty() && reference.referenceFrom != reference.label)
      throw PathwayError("chart configuration \"" + config.source + "\": reference=" +
                         reference.label + " takes its own reference from another configuration");
    const std::string difference =
        expectedImageDifference(reference.choices.recipe().params, config.choices.recipe().params);
    if (!difference.empty())
      throw PathwayError("chart configuration \"" + config.source +
                         "\": reference=" + reference.label + " renders with " + difference +
                         ", so it estimates another image");
    if (sceneOf(reference) != sceneOf(config) ||
        reference.choices.filter != config.choices.filter ||
        reference.choices.filterRadius != config.choices.filterRadius)
      throw PathwayError("chart configuration \"" + config.source +
                         "\": reference=" + reference.label +
                         " renders another scene or with another filter, so it estimates "
                         "another image");
  }
}

}  // namespace pathway
