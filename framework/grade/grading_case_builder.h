// Declaring a grading case one setting at a time (grading_cases.cpp, course_cases.cpp).
#pragma once

#include <string>
#include <utility>

#include "grade/grading_cases.h"

namespace pathway {

// A case at the defaults (96x96, box filter, the stage's own sampler), changed one setting at a
// time, so that a table of cases reads as a list of what each case does differently.
struct CaseBuilder {
  GradingCase c;
  CaseBuilder(int stage, std::string name, std::string scene, std::string purpose) {
    c.stage = stage;
    c.name = std::move(name);
    c.scene = std::move(scene);
    c.purpose = std::move(purpose);
  }
  CaseBuilder& param(const std::string& name, const std::string& value) {
    c.params[name] = value;
    return *this;
  }
  CaseBuilder& filter(FilterType type, float radius = 0.0f) {
    c.filter = type;
    c.filterRadius = radius;
    return *this;
  }
  CaseBuilder& sobol() {
    c.sobol = true;
    return *this;
  }
  CaseBuilder& size(int width, int height) {
    c.width = width;
    c.height = height;
    return *this;
  }
  CaseBuilder& spp(uint32_t samples) {
    c.spp = samples;
    return *this;
  }
  CaseBuilder& tiles(int size) {
    c.tileSize = size;
    return *this;
  }
  CaseBuilder& requiresTechnique(double noiseBound, std::string technique) {
    c.noiseBound = noiseBound;
    c.requiredTechnique = std::move(technique);
    return *this;
  }
};

}  // namespace pathway
