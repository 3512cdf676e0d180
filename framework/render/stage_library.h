// Student stages built on their own, into a shared library that the running program loads: the
// grader builds each submission (and each planted bug of the mutant suite) this way, instead of
// building the whole program again. Loading it registers its stages over the built-in student
// stages ("stageN"); the reference stages stay as they are.
#pragma once

#include <string>
#include <vector>

namespace pathway {

// Loads `path` (once per process; it stays loaded). Throws PathwayError naming the file and the
// loader's reason (missing file, undefined symbol, ...). Returns the stages it registered.
std::vector<int> loadStageLibrary(const std::string& path);

// How to compile stage files into such a library with this build's compiler and flags: the
// program and its arguments; append the sources, "-o" and the library's path.
std::vector<std::string> stageLibraryCompileCommand();

}  // namespace pathway
