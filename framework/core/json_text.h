// JSON that other programs read (results.json for Gradescope, chart summaries for matplotlib),
// written with nlohmann-json: keys in the order written, two-space indent, and text that is not
// valid UTF-8 (a compiler's message cut inside a character, a stage printing bytes) with U+FFFD
// in its place, since JSON readers refuse invalid UTF-8. Non-finite numbers are written as null.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

namespace pathway {

using Json = nlohmann::ordered_json;

inline std::string jsonText(const Json& value) {
  return value.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
}

}  // namespace pathway
