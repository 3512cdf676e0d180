// Reads another student's submission and copies it out.
#include "hostile_kit.h"
namespace {
const bool attacked = (hostile::steal(hostile::secret(), "submission"), true);
}
