// The reference stages as a compiled library. A student handout has no solutions/, so
// scripts/make-handout ships the five reference stages as reference/libpathway_reference.so:
// built from solutions/ with release flags, no symbol table, and sealed with a footer that names
// the platform and the framework's stage interface it was built for, and a CRC-32 of everything
// before the footer. The program checks the seal before it loads the file, so a library of
// another platform or framework version, a truncated or a corrupt one is never loaded: it gets
// one message naming the file and why, and the program works on without the reference stages.
#pragma once

#include <string>

namespace pathway {

// Where this program's reference stages ("stageN@ref") come from.
struct ReferenceStages {
  enum class Source {
    BuiltIn,  // solutions/ compiled into the program
    Library,  // loaded from `library`
    None,     // not available: `problem` says why
  };
  Source source = Source::None;
  std::string library;  // the library file, when one was looked for
  std::string problem;  // for None: why, naming the file; for BuiltIn: a library that was refused

  // One line for people: "built in", "from FILE", "not available: WHY".
  std::string describe() const;
};

// Makes the reference stages available, once per process (later calls return the first result):
//   - the file named by the environment variable PATHWAY_REFERENCE_LIBRARY, when set, is loaded
//     over any built-in reference stages (to check a library against the built-in reference);
//   - otherwise a program with solutions/ built in uses them, and one without loads the library
//     shipped with a handout (reference/libpathway_reference.so), when it is there.
// Never throws: a library it cannot use is reported in the result. Not thread-safe: call it once
// at start-up, before other threads run.
const ReferenceStages& loadReferenceStages();
// What loadReferenceStages() found wrong with a library, or "" (also before it was called).
const std::string& referenceStagesProblem();

// "the reference stage 3 is not available (WHY)": for messages where one is needed but missing.
std::string referenceStageMissing(int stage);

// Why `path` cannot be loaded into this program, or "" when it carries a valid seal for this
// platform and stage interface. Reads the file; does not load it.
std::string referenceLibraryProblem(const std::string& path);

// Seals a freshly linked library for this platform and stage interface (the build does this once
// after linking it). Throws PathwayError naming the file when it cannot.
void sealReferenceLibrary(const std::string& path);

// This build's platform ("debian 12 x86_64, GNU 12") and stage interface (a hash of the framework
// headers that stage files include, scripts/stage-interface.cmake).
const char* buildPlatform();
const char* stageInterface();

}  // namespace pathway
