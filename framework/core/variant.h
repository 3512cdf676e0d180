// Each stage exists twice: the student's version (assignments/) and the reference (solutions/).
// Both can be linked into one program, so the viewer and grader can show them side by side.
#pragma once

namespace pathway {

enum class Variant { Student, Reference };

inline const char* variantName(Variant variant) {
  return variant == Variant::Student ? "student" : "reference";
}

}  // namespace pathway
