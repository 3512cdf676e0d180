#include "core/text_output.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace pathway {

namespace fs = std::filesystem;

std::string validUtf8(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size();) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const size_t length = lead < 0x80           ? 1
                          : (lead >> 5) == 0x6  ? 2
                          : (lead >> 4) == 0xE  ? 3
                          : (lead >> 3) == 0x1E ? 4
                                                : 0;
    bool valid = length > 0 && i + length <= text.size();
    for (size_t k = 1; valid && k < length; ++k)
      valid = (static_cast<unsigned char>(text[i + k]) >> 6) == 0x2;
    if (valid) {
      out.append(text, i, length);
      i += length;
    } else {
      out += "\xEF\xBF\xBD";
      ++i;
    }
  }
  return out;
}

std::string jsonString(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : validUtf8(text)) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c < 0x20) {
          char escaped[8];
          std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
          out += escaped;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

// Writes `text` to a temporary file beside `path`, then renames it into place.
void writeTextAtomically(const std::string& path, const std::string& text) {
  const fs::path target(path);
  std::error_code ignored;
  if (target.has_parent_path()) fs::create_directories(target.parent_path(), ignored);
  if (target.has_parent_path() && !fs::is_directory(target.parent_path()))
    throw PathwayError(path + ": cannot create the folder " + target.parent_path().string());
  const fs::path temporary = target.parent_path() / (".partial-" + target.filename().string());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << text;
    if (!out.flush()) throw PathwayError(path + ": writing failed");
  }
  std::error_code error;
  fs::rename(temporary, target, error);
  if (error) throw PathwayError(path + ": could not move the finished file into place");
}

}  // namespace pathway
