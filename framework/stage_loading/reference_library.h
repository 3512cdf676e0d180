// The reference stages as a compiled library. A student handout has no solutions/, so
// scripts/make-handout ships the five reference stages as reference/libpathway_reference.so:
// built from solutions/ with release flags, no symbol table, and sealed with a footer that names
// the platform (processor and C++ ABI), the framework's stage interface and the layout of the
// types the library shares with the program, and a CRC-32 of everything before the footer. The
// program checks the seal before it loads the file, so a library of another platform or
// framework version, a truncated or a corrupt one is never loaded: it gets one message naming the
// file and why, and the program works on without the reference stages. The distribution is not
// part of the platform: one library serves Debian 12 and 13 (scripts/make-handout checks that it
// needs no newer C or C++ runtime than Debian 12 has).
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
// Never throws: a library it cannot use is reported in the result, and noted in the registry for
// each stage (referenceStageMissing in render/integrator_registry.h). Not thread-safe: call it once
// at start-up, before other threads run.
const ReferenceStages& loadReferenceStages();
// What loadReferenceStages() found wrong with a library, or "" (also before it was called).
const std::string& referenceStagesProblem();

// Why `path` cannot be loaded into this program, or "" when it carries a valid seal for this
// platform and stage interface. Reads the file; does not load it.
std::string referenceLibraryProblem(const std::string& path);

// Seals a freshly linked library for this platform and stage interface (the build does this once
// after linking it). Throws PathwayError naming the file when it cannot.
void sealReferenceLibrary(const std::string& path);

// This build's platform ("Linux x86_64, GNU C++"), stage interface (a hash of the framework
// headers that stage files include, scripts/stage-interface.cmake) and the sizes of the types a
// stage library shares with the program ("Vec3 12, Ray 28, ...").
const char* buildPlatform();
const char* stageInterface();
std::string interfaceLayout();

}  // namespace pathway
