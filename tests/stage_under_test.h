// Which version of the stages the stage tests check.
//
// By default they check the reference stages (built in, or in a handout the compiled reference
// library), and are skipped where there are none. With PATHWAY_TEST_STUDENT=1 in the environment
// they check the student's stages instead ("stageN", the files in assignments/), so students can
// run the course's own analytic tests on their work:  PATHWAY_TEST_STUDENT=1 ctest --preset release
// -R "Stage|Film|PixelFilter"
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "core/variant.h"
#include "render/integrator_registry.h"
#include "render/stage_kit.h"

namespace pathway::test {

inline bool checkingStudentCode() {
  const char* value = std::getenv("PATHWAY_TEST_STUDENT");
  return value && *value && std::string(value) != "0";
}

inline Variant variantUnderTest() {
  return checkingStudentCode() ? Variant::Student : Variant::Reference;
}

// "stage2@ref" (default) or "stage2" (PATHWAY_TEST_STUDENT=1).
inline std::string stage(int number) {
  return stageIntegratorName(number, variantUnderTest());
}

// The stage 1 functions (filters, splat) under test.
inline const Stage1Functions& stage1UnderTest() {
  return StageKit(1, variantUnderTest(), EarlierStages::Own).stage1();
}

// A full repository: solutions/ built into the program, assignments/ holding the untouched
// skeletons. In a student handout solutions/ is not there, and assignments/ holds the student's
// own work, finished or not.
#ifdef PATHWAY_HAS_SOLUTIONS
constexpr bool kFullRepository = true;
#else
constexpr bool kFullRepository = false;
#endif

// Whether the reference stages are there: built in, or a handout's compiled library
// (stage_loading/reference_library.h, loaded by tests/reference_stages.cpp as the program loads
// it).
inline bool haveReference() {
  return findStageIntegrator(1, Variant::Reference) != nullptr;
}

}  // namespace pathway::test

#define PATHWAY_REQUIRE_REFERENCE()                                                 \
  if (!::pathway::test::checkingStudentCode() && !::pathway::test::haveReference()) \
  GTEST_SKIP() << "no reference stages here (PATHWAY_TEST_STUDENT=1 checks your stages)"
