// Text files other programs read (results.json for Gradescope, chart data for matplotlib):
// JSON string quoting and whole-file writes that never leave a half-written file behind.
#pragma once

#include <string>

namespace pathway {

// The text with every invalid UTF-8 sequence (a compiler's output cut in the middle of a
// character, a stage printing bytes) replaced by U+FFFD: JSON readers refuse invalid UTF-8.
std::string validUtf8(const std::string& text);

// `text` as a quoted JSON string, valid UTF-8, control characters escaped.
std::string jsonString(const std::string& text);

// Writes `text` to a temporary file beside `path`, then renames it into place; creates the
// folder. Throws PathwayError naming the path when it cannot.
void writeTextAtomically(const std::string& path, const std::string& text);

}  // namespace pathway
