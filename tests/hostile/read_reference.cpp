// Reads a shipped grading reference and copies it out.
#include "hostile_kit.h"
namespace {
const bool attacked = (hostile::steal(hostile::reference(), "reference"), true);
}
