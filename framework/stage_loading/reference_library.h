// The reference stages as compiled libraries, one per stage: reference/stage1.so ... stage5.so.
// The grader's child (grade/case_render_job.h) loads only those it may hold: for a student's
// stage N, the reference's stages below N, so the process that runs student code never contains
// the reference of the stage it grades, or of any later one. Library N holds the code of the
// solution files 1..N but registers stage N alone. (Stage 3's wavefront version is stage 2's wave
// with one AO ray: that code is stage 2's, in library 2 too, registered as stage 3 by library 3.)
// The build makes them from solutions/ (build/<preset>/reference/); a student handout has no
// solutions/, so scripts/make-handout ships them in reference/, where the program loads all five.
// Each is built with release flags, no symbol table, and sealed with a footer that names
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
    Library,  // loaded from the libraries in `library`
    None,     // not available: `problem` says why
  };
  Source source = Source::None;
  std::string library;  // the libraries' folder, when they were looked for
  std::string problem;  // for None: why, naming the file; for BuiltIn: a library that was refused

  // One line for people: "built in", "from FILE", "not available: WHY".
  std::string describe() const;
};

// The folder of the five libraries: the one named by the environment variable
// PATHWAY_REFERENCE_LIBRARIES when set (to check libraries against the built-in reference), else
// this build's (build/<preset>/reference, or a handout's reference/).
std::string referenceLibraryFolder();
// The library of reference stage `stage` in `folder` ("FOLDER/stage3.so"), by default that one.
std::string referenceStageLibrary(int stage, const std::string& folder = referenceLibraryFolder());
// Why the five libraries cannot all be used (the first one refused, and why), or "".
std::string referenceLibrariesProblem();
// Loads the library of reference stage `stage` (its seal checked first). Throws PathwayError
// naming the file and why, when it cannot.
void loadReferenceStageLibrary(const std::string& path, int stage);

// Makes the reference stages available, once per process (later calls return the first result):
//   - the libraries of PATHWAY_REFERENCE_LIBRARIES, when set, are loaded over any built-in
//     reference stages;
//   - otherwise a program with solutions/ built in uses them, and one without loads the five
//     libraries shipped with a handout (reference/stageN.so), when they are all there.
// Never throws: libraries it cannot use are reported in the result, and noted in the registry for
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
