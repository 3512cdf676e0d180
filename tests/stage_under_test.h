// Which version of the stages the stage tests check.
//
// By default they check the reference solutions, and in a student handout (no solutions/) they
// are skipped. With PATHWAY_TEST_STUDENT=1 in the environment they check the student's stages
// instead ("stageN", the files in assignments/), so students can run the course's own analytic
// tests on their work:  PATHWAY_TEST_STUDENT=1 ctest --preset release -R "Stage|Film|PixelFilter"
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

#ifdef PATHWAY_HAS_SOLUTIONS
constexpr bool kHaveSolutions = true;
#else
constexpr bool kHaveSolutions = false;
#endif

}  // namespace pathway::test

#define PATHWAY_REQUIRE_SOLUTIONS()                                                \
  if (!::pathway::test::checkingStudentCode() && !::pathway::test::kHaveSolutions) \
  GTEST_SKIP() << "built without solutions/ (PATHWAY_TEST_STUDENT=1 checks your stages)"
