// Fills the disk within the per-file limit: 25 files of 16 MiB (400 MiB) in its own folder.
#include <fstream>
#include <string>
#include <vector>

#include "hostile_kit.h"
namespace {
const bool attacked = [] {
  const std::string folder = hostile::outputFolder();
  const std::vector<char> block(16 << 20, 'x');
  for (int i = 0; i < 25 && !folder.empty(); ++i)
    std::ofstream(folder + "/filler" + std::to_string(i), std::ios::binary)
        .write(block.data(), static_cast<std::streamsize>(block.size()));
  return true;
}();
}  // namespace
