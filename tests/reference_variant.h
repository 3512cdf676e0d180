// Tests of stage code run against the reference solutions; in a student handout (no solutions/)
// they are skipped with a note rather than failing.
#pragma once

#include <gtest/gtest.h>

#ifdef PATHWAY_HAS_SOLUTIONS
#define PATHWAY_REQUIRE_SOLUTIONS() (void)0
#else
#define PATHWAY_REQUIRE_SOLUTIONS() GTEST_SKIP() << "built without solutions/"
#endif
