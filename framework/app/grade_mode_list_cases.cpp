// `pathway grade --list-cases`: every grading case with its scene, settings and what it is there
// to catch. Also what `pathway cluster grade` runs to check its grade options before submitting.
#include <cstdio>
#include <string>

#include "app/grade_modes.h"

namespace pathway {

int listCasesMode(const GradeOptions&) {
  std::printf("%-30s %-26s %-9s %4s %4s %7s  %s\n", "case", "scene", "filter", "spp", "tile",
              "size", "parameters: what it is there to catch");
  for (const GradingCase& c : gradingCases()) {
    std::string params;
    for (const auto& [name, value] : c.params) params += name + "=" + value + " ";
    const std::string size = std::to_string(c.width) + "x" + std::to_string(c.height);
    std::printf("%-30s %-26s %-9s %4u %4d %7s  %s%s%s%s\n", c.id().c_str(), c.scene.c_str(),
                filterTypeName(c.filter).c_str(), c.spp, c.tileSize, size.c_str(), params.c_str(),
                c.sobol ? "(sobol) " : "", c.courseOnly ? "(course only) " : "", c.purpose.c_str());
  }
  return 0;
}

}  // namespace pathway
