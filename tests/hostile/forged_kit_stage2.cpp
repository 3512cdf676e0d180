// Stage 2 graded on the reference's stage 1: the forged kit's stage 2 (the reference's nested AO
// functions) handed on as the student's. The child for stage 2 holds the reference's stage 1
// only.
#include "forged_kit.h"
namespace {
const bool attacked =
    (pathway::provideStage2(pathway::Variant::Student, hostile::forgedReferenceKit().stage2()),
     true);
}  // namespace
