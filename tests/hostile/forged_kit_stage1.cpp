// The reference handed on as the student's own: an object laid out like StageKit (its two
// variants, both the reference's), and its stage 1 handed on through the exported provideStage1.
// It works only where the process holds the reference's stage 1; the grader's child for stage 1
// holds none, so the kit has nothing to give.
#include "forged_kit.h"
namespace {
const bool attacked =
    (pathway::provideStage1(pathway::Variant::Student, hostile::forgedReferenceKit().stage1()),
     true);
}  // namespace
