// The masks a grading reference stores beside its mean so that the grader can say where a wrong
// image differs (difference_diagnosis.h): they are made with the reference stages, once, when the
// references are made.
//   - pattern.escaped (every stage): the background, weighted by the share of camera rays that
//     leave the scene through each pixel;
//   - pattern.occluded (stages 2, 3): the same AO with rays too short to be blocked, minus the
//     reference: how much each pixel is occluded;
//   - pattern.direct and pattern.indirect (stages 4, 5): the case at depth 1 minus depth 0 (light
//     one bounce from the emitters), and the reference minus depth 1 (light after more bounces);
//   - pattern.skyLit and pattern.skyLitOnce (stages 4, 5, scenes with a background): the case
//     with every emitter dark minus the same at depth 0, at the case's depth and at depth 1: the
//     background's light on surfaces, after any number of bounces and after one (bounce rays
//     that leave the scene return the background at every depth, so pattern.direct holds the
//     second, and pattern.indirect part of the first);
//   - pattern.oneBounceMore (stages 4, 5, a finite depth): the case one bounce deeper, minus the
//     reference: what a depth test that lets paths go one step too far adds;
//   - pattern.movedRight, movedDown, widerFilter and pattern.moved.I.J (stage 1): the image moved
//     by a pixel to first order, the filter's width, and each half-pixel move as rendered;
// A pattern that is zero everywhere (no background; a case of depth 1 has no indirect light) is
// left out; the others are stored as tile means (the diagnosis reads no finer).
#pragma once

#include <map>
#include <string>

#include "film/film.h"
#include "grade/grading_cases.h"
#include "scene/ray_tracer.h"

namespace pathway {

// a + sign·b, or a where there is no b: how the patterns are made from renders, and combined.
Image sumOfImages(const Image& a, const Image* b, float sign = 1.0f);

// `renderVariance`: the mean of the replicates' own per-pixel variance estimates, stored as
// pattern.renderVariance (not fitted: held against a render's own).
std::map<std::string, Image> makeDifferencePatterns(const GradingCase& gradingCase,
                                                    const RayTracer& tracer,
                                                    const Image& referenceMean,
                                                    const Image& renderVariance,
                                                    ReferenceTracing tracing);

}  // namespace pathway
