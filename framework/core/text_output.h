// Text files other programs read (results.json for Gradescope, chart data for matplotlib) are
// written whole or not at all: never a half-written file.
#pragma once

#include <string>

namespace pathway {

// Writes `text` to a temporary file beside `path`, then renames it into place; creates the
// folder. Throws PathwayError naming the path when it cannot.
void writeTextAtomically(const std::string& path, const std::string& text);

}  // namespace pathway
