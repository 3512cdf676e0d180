// The student's stages as the program renders them. CMake builds each stage file of assignments/
// into its own library (build/<preset>/stages/stageN.so) instead of linking it into the program,
// so that a stage that does not compile costs only itself. The commands that render a student's
// stage (render, view, chart) load them; the grader never does (it builds the stage files itself,
// as the autograder does, and only its sandboxed child loads them).
#pragma once

namespace pathway {

// Loads every student stage library this build made, once; a stage whose library is missing or
// cannot be loaded is not fatal (the other stages still render): why is noted in the registry
// (render/integrator_registry.h), e.g. "assignments/stage3/stage3_ao_4d.cpp did not compile
// (scripts/build shows the compiler's message)", and shown when the stage is asked for.
void loadStudentStages();

}  // namespace pathway
