#include "core/text_output.h"

#include <filesystem>
#include <fstream>

#include "core/error.h"

namespace pathway {

namespace fs = std::filesystem;

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
