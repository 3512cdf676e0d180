#include "core/regular_file_copy.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace pathway {

namespace fs = std::filesystem;

bool copyRegularFile(const fs::path& from, const fs::path& to, uintmax_t most) {
  const int in = ::open(from.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
  if (in < 0) return false;
  struct stat info {};
  const bool regular = ::fstat(in, &info) == 0 && S_ISREG(info.st_mode) &&
                       static_cast<uintmax_t>(info.st_size) <= most;
  std::string bytes;
  char buffer[1 << 16];
  for (ssize_t n; regular && (n = ::read(in, buffer, sizeof buffer)) > 0;) bytes.append(buffer, n);
  ::close(in);
  if (!regular) return false;
  std::error_code error;
  fs::create_directories(to.parent_path(), error);
  std::ofstream out(to, std::ios::binary | std::ios::trunc);
  if (!(out << bytes) || !out.flush()) return false;
  fs::permissions(to,
                  fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                      fs::perms::others_read,
                  error);
  return true;
}

}  // namespace pathway
