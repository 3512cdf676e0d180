// Stages built on their own, into a shared library that the running program loads: the grader
// builds each submission (and each planted bug of the mutant suite) this way, instead of building
// the whole program again, and a handout ships the reference stages this way
// (stage_loading/reference_library.h). Loading a library registers its stages over the built-in
// ones of the same name ("stageN", or "stageN@ref").
#pragma once

#include <string>
#include <vector>

#include "core/variant.h"

namespace pathway {

// Loads `path` (once per process; it stays loaded) as `variant`'s stage `stage` (0: whichever one
// stage it registers): it may register that and nothing else (render/registration_gate.h; a
// reference library's registrations of other stages, whose code it carries, are skipped). Throws
// PathwayError naming the file and the loader's reason (missing file, undefined symbol, a
// registration refused, ...). Returns the stages of `variant` it registered.
std::vector<int> loadStageLibrary(const std::string& path, Variant variant = Variant::Student,
                                  int stage = 0);

// How to compile stage files into such a library with this build's compiler and flags: the
// program and its arguments; append the sources, "-o" and the library's path.
std::vector<std::string> stageLibraryCompileCommand();

}  // namespace pathway
