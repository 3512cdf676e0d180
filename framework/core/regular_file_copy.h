// A copy that never follows a link: what the grader hands from a folder it does not trust (a
// submission, a compiler's build folder) to the sandbox's user.
#pragma once

#include <cstdint>
#include <filesystem>

namespace pathway {

// Copies the regular file `from` to `to` (its folders made), readable by all, if it has at most
// `most` bytes; false when it is no such file. Read through one descriptor opened without
// following a link: a symbolic link to a file of the grading machine is never followed, nor
// swapped in between a check and the copy.
bool copyRegularFile(const std::filesystem::path& from, const std::filesystem::path& to,
                     uintmax_t most = UINTMAX_MAX);

}  // namespace pathway
