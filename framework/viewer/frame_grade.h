// Grading what the viewer shows (key G): the reference of the shown stage renders the same view
// with the same settings and at least as many samples, and the shown image is compared with it
// tile by tile (grade/image_comparison.h, from the two images' own variances). The signed-z
// heatmap goes over the pane, so a student sees where their image is wrong.
#pragma once

#include <string>

#include "grade/image_comparison.h"
#include "viewer/loaded_scene.h"
#include "viewer/render_worker.h"

namespace pathway {

struct FrameGrade {
  uint64_t job = 0;        // the job of the frame that was graded ...
  uint32_t spp = 0;        // ... and how far it had come
  std::string integrator;  // what was graded, and against what
  std::string reference;
  Comparison comparison;
  Image heatmap;        // image-sized, linear RGB
  std::string summary;  // one or two lines for the pane
  std::string error;    // the grade could not be made (no reference built in, ...)
  bool passed = false;
};

// Whether `frame` shows a stage whose reference is built in (and so can be graded).
bool canGradeFrame(const LaneFrame& frame);

// Renders the reference (blocking: run it off the UI thread) and compares. Never throws.
FrameGrade gradeFrame(const LaneFrame& frame, const LoadedScene& scene);

}  // namespace pathway
