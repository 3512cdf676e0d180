// A private temporary folder that cleans up after itself.
#pragma once

#include <string>

namespace pathway {

// A new, private folder under the system's temporary folder, or under `parent` (mkdtemp), removed
// with everything in it when the object goes, also when an exception passes.
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const std::string& prefix, const std::string& parent = "");
  ~TemporaryFolder();
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace pathway
