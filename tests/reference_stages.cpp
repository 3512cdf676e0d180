// The tests see the reference stages the pathway program sees: built in, or in a handout the
// compiled reference library (stage_loading/reference_library.h), loaded before the first test runs
// (not while static objects are built: the built-in stages register then, in any order).
#include <gtest/gtest.h>

#include "stage_loading/reference_library.h"

namespace {

class ReferenceStagesLoaded : public ::testing::Environment {
 public:
  void SetUp() override { pathway::loadReferenceStages(); }
};

const auto* environment = ::testing::AddGlobalTestEnvironment(new ReferenceStagesLoaded);

}  // namespace
