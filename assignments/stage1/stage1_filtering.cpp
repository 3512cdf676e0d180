// Stage 1 - filtered supersampling (your file).
//
// A pixel is not a point sample: pixel j's value is the image radiance L weighted by a filter f
// centred on the pixel,
//     I_j = ∫ f(x - x_j, y - y_j) L(x, y) dx dy  /  ∫ f(x - x_j, y - y_j) dx dy.
// Estimate numerator and denominator with the SAME samples: every sample adds f_j·L and f_j to
// every pixel j whose filter reaches it, and the film divides the two sums at the end. (The road
// not taken, filter importance sampling, draws each pixel's own positions with density ∝ |f| so
// that a sample serves one pixel with weight ±1; here every sample serves all the pixels it
// reaches, so the weights stay in the sums.)
//
// Your part: the four filter profiles and the splat (the TODOs below; README.md beside this file
// explains them). The shading (albedo lit from the eye) is given by the framework.
#include <algorithm>
#include <cmath>

#include "render/stage_api.h"
#include "stages/stage1.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// ---- 1D filter profiles, on their natural support; the 2D filter is f(x)·f(y). ----

// Placeholder shape used until a profile is written: the box.
float placeholderProfile(float x) {
  return std::fabs(x) <= 0.5f ? 1.0f : 0.0f;
}

float boxFilter(float x) {
  PATHWAY_TODO("box filter: 1 on [-0.5, 0.5], 0 elsewhere");
  return placeholderProfile(x);
}

float tentFilter(float x) {
  PATHWAY_TODO("tent filter: 1 - |x| on [-1, 1], 0 elsewhere");
  return placeholderProfile(x);
}

float mitchellNetravaliFilter(float x) {
  PATHWAY_TODO("Mitchell-Netravali filter with B = C = 1/3 on [-2, 2] (see README.md)");
  return placeholderProfile(x);
}

float gaussianFilter(float x, float sigma) {
  PATHWAY_TODO("Gaussian exp(-x^2 / (2 sigma^2)), cut to 0 beyond 3 sigma");
  (void)sigma;
  return placeholderProfile(x);
}

// ---- The splat: one sample at film position p (in pixels) with radiance L. ----
// The estimator: n samples p_i spread over the film with a constant density pdf estimate the
// two integrals of I_j by (1/n) Σ_i f_j(p_i)·L(p_i) / pdf and (1/n) Σ_i f_j(p_i) / pdf. In their
// ratio, Σ_i f_j(p_i)·L(p_i) / Σ_i f_j(p_i), n and pdf cancel: so each sample adds f_j·L and f_j,
// and the film divides.
// Pixel (x, y) covers [x, x+1) x [y, y+1); its centre is (x + 0.5, y + 0.5).
// filter.radius() is the support; filter.evaluate(dx, dy) is f(dx)·f(dy).
// film.addSample(x, y, weight, radiance) adds weight·radiance and weight to pixel (x, y)
// (pixels outside the image are ignored for you).
void splat(FilmBlock& film, Vec2 p, const Color& radiance, const PixelFilter& filter) {
  PATHWAY_TODO("splat: add f_j * L and f_j to every pixel j within filter.radius() of p");
  (void)filter;
  // Placeholder: the sample lands in its own pixel only, with weight 1.
  film.addSample(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)), 1.0f,
                 radiance);
}

// Stage 1 hands its filters and splat on to every later stage; its shading is the framework's
// eye light.
const bool registered = registerStage<EyeLightIntegrator>(
    stage1(),
    Stage1Functions{{boxFilter, tentFilter, mitchellNetravaliFilter, gaussianFilter}, splat});

}  // namespace
}  // namespace pathway
