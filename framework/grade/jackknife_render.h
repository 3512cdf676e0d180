// A grading render that carries its own variance. The grader judges a submission's expectation,
// not its noise: a valid method may be noisier than the reference's (another roulette rule,
// uniform directions with their pdf), so the whole-image tests need the submission's own variance
// of a block of pixels' mean, with the filter's correlations and the heavy tails as they are.
//
// One render gives it for free, by the jackknife: its samples are drawn in B passes of spp / B
// (batches), and besides the whole image the render is developed B more times, each time without
// one batch (the film's sums minus that batch's). For any block, Var(mean) ≈ (B - 1)/B ·
// Σ_j (m_without_j - their average)², with about B - 1 degrees of freedom. Leaving one batch out
// keeps each image near the whole render's spp, so the ratio Σ w·L / Σ w (a negative-lobed filter
// at low spp) behaves as in the render itself; stratified or low-discrepancy samples only make the
// estimate too large, never too small. The whole image is the render it always was.
#pragma once

#include <cstdint>

#include "engine/render_session.h"

namespace pathway {

// The most batches a render is cut into: more degrees of freedom for the variance, fewer samples
// per batch (a batch needs at least one sample per pixel).
inline constexpr uint32_t kMostSampleBatches = 8;

// The number of batches for `spp` samples per pixel: the largest divisor of spp up to
// kMostSampleBatches, so that every batch has as many samples (1: no jackknife).
uint32_t sampleBatchCount(uint32_t spp);

// Renders `recipe` as runRender does; with `jackknife`, result.images.jackknife filled in (one
// image per batch, the render without it; written with the render as layers jackknife0, ...).
RenderResult renderWithJackknife(const RayTracer& tracer, const RenderRecipe& recipe,
                                 bool jackknife);

}  // namespace pathway
