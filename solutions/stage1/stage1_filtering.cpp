// Stage 1 - filtered supersampling (reference solution).
//
// A pixel is not a point sample: pixel j's value is the image radiance L weighted by a filter f
// centred on the pixel,
//     I_j = ∫ f(x - x_j, y - y_j) L(x, y) dx dy  /  ∫ f(x - x_j, y - y_j) dx dy.
// We estimate numerator and denominator with the SAME samples: every sample adds f_j·L and f_j to
// every pixel j whose filter reaches it, and the film divides the two sums at the end. Normalising
// numerically like this makes a constant image come back exactly constant, whatever the filter's
// own integral and wherever the samples fell.
//
// Your part: the four filter profiles and the splat. The shading (albedo lit from the eye) is
// given by the framework: it has no noise of its own, so what you see is the pixel integral.
#include <algorithm>
#include <cmath>

#include "render/stage_api.h"
#include "render/wavefront.h"
#include "stages/stage1.h"  // the stage's parameters: setup.params.<field>

namespace pathway {
namespace {

// ---- 1D filter profiles, on their natural support; the 2D filter is f(x)·f(y). ----

float boxFilter(float x) {
  return std::fabs(x) <= 0.5f ? 1.0f : 0.0f;
}

float tentFilter(float x) {
  return std::max(0.0f, 1.0f - std::fabs(x));
}

// Mitchell-Netravali with B = C = 1/3: a cubic that is sharper than the tent and rings less than
// sinc. Its negative lobes (1 < |x| < 2) are why Σ f can be close to 0 at low sample counts.
float mitchellNetravaliFilter(float x) {
  const float a = std::fabs(x);
  if (a < 1.0f) return (7.0f * a * a * a - 12.0f * a * a + 16.0f / 3.0f) / 6.0f;
  if (a <= 2.0f)
    return (-7.0f / 3.0f * a * a * a + 12.0f * a * a - 20.0f * a + 32.0f / 3.0f) / 6.0f;
  return 0.0f;
}

// Unnormalised Gaussian, cut at 3σ. The film's division by Σ f makes the missing tail harmless.
float gaussianFilter(float x, float sigma) {
  if (std::fabs(x) > 3.0f * sigma) return 0.0f;
  return std::exp(-x * x / (2.0f * sigma * sigma));
}

// ---- The splat: one sample at film position p (pixels) with radiance L. ----
// The estimator: n samples p_i spread over the film with a constant density pdf estimate the
// two integrals of I_j by (1/n) Σ_i f_j(p_i)·L(p_i) / pdf and (1/n) Σ_i f_j(p_i) / pdf. In their
// ratio, Σ_i f_j(p_i)·L(p_i) / Σ_i f_j(p_i), n and pdf cancel: so each sample adds f_j·L and f_j,
// and the film divides.
void splat(FilmBlock& film, Vec2 p, const Color& radiance, const PixelFilter& filter) {
  // Pixel j covers [j, j+1), so its centre is at j + 0.5; it is in reach when
  // |p - (j + 0.5)| <= radius, i.e. j in [p - 0.5 - radius, p - 0.5 + radius].
  const float r = filter.radius();
  const int xFirst = static_cast<int>(std::ceil(p.x - 0.5f - r));
  const int xLast = static_cast<int>(std::floor(p.x - 0.5f + r));
  const int yFirst = static_cast<int>(std::ceil(p.y - 0.5f - r));
  const int yLast = static_cast<int>(std::floor(p.y - 0.5f + r));
  for (int y = yFirst; y <= yLast; ++y) {
    for (int x = xFirst; x <= xLast; ++x) {
      const float weight = filter.evaluate(p.x - (x + 0.5f), p.y - (y + 0.5f));
      // Numerator (f·L) and denominator (f) from the same sample: the film adds both.
      if (weight != 0.0f) film.addSample(x, y, weight, radiance);
    }
  }
}

#ifdef PATHWAY_VARIANT_REFERENCE
// The same splat, faster, for the reference build, whose splat every reference render of every
// stage calls. The 2D filter is f(dx)·f(dy) (PixelFilter::evaluate), so the profile is evaluated
// once per column and once per row in reach instead of twice per pixel; each pixel gets the same
// product of the same two floats, in the same order, so the film's sums are bit for bit the
// splat's above (test: Film.ReferenceSplatAddsExactlyTheDefinitionsSums). A window wider than
// its arrays (17 pixels, at the largest radius, 8) goes to the splat above.
void separableSplat(FilmBlock& film, Vec2 p, const Color& radiance, const PixelFilter& filter) {
  constexpr int kMostInReach = 16;
  const float r = filter.radius();
  const int xFirst = static_cast<int>(std::ceil(p.x - 0.5f - r));
  const int xLast = static_cast<int>(std::floor(p.x - 0.5f + r));
  const int yFirst = static_cast<int>(std::ceil(p.y - 0.5f - r));
  const int yLast = static_cast<int>(std::floor(p.y - 0.5f + r));
  if (xLast - xFirst >= kMostInReach || yLast - yFirst >= kMostInReach)
    return splat(film, p, radiance, filter);
  float columnWeight[kMostInReach], rowWeight[kMostInReach];
  for (int x = xFirst; x <= xLast; ++x)
    columnWeight[x - xFirst] = filter.evaluate1D(p.x - (x + 0.5f));
  for (int y = yFirst; y <= yLast; ++y) rowWeight[y - yFirst] = filter.evaluate1D(p.y - (y + 0.5f));
  for (int y = yFirst; y <= yLast; ++y) {
    if (rowWeight[y - yFirst] == 0.0f) continue;  // then every weight of the row is 0
    for (int x = xFirst; x <= xLast; ++x) {
      const float weight = columnWeight[x - xFirst] * rowWeight[y - yFirst];
      if (weight != 0.0f) film.addSample(x, y, weight, radiance);
    }
  }
}
constexpr auto kHandedOnSplat = separableSplat;
#else
constexpr auto kHandedOnSplat = splat;
#endif

// Stage 1 hands its filters and splat on to every later stage; its shading is the framework's
// eye light.
const bool registered = registerStage<EyeLightIntegrator>(
    stage1(), Stage1Functions{{boxFilter, tentFilter, mitchellNetravaliFilter, gaussianFilter},
                              kHandedOnSplat});

// The wavefront version, "stage1@fast", for the renders that are not student code (references,
// calibration): a batch's camera rays traced together in 16-ray Embree packets (a packet's rays
// are samples of one or two pixels, so they are close to one ray), then shaded by the eye light
// one by one, as EyeLightIntegrator::Li shades. Its image equals stage1@ref's wherever the
// packets report the hits single rays do (test: WavefrontStages.*).
class WavefrontEyeLight : public WavefrontIntegrator {
 public:
  explicit WavefrontEyeLight(const StageSetup<Stage1Params>&) {}

  void LiBatch(CameraSampleBatch& batch, const RenderContext& context) const override {
    const size_t n = batch.size();
    thread_local std::vector<std::optional<SurfaceHit>> hits;
    thread_local std::vector<uint32_t> every;
    hits.resize(n);
    every.resize(n);
    for (uint32_t i = 0; i < n; ++i) every[i] = i;
    intersectAll(context, batch.cameraRays, every, RayKind::Primary, hits);
    batch.radiance.resize(n);
    batch.rays.assign(n, 1);
    for (size_t i = 0; i < n; ++i)
      batch.radiance[i] =
          hits[i] ? eyeLightShading(*hits[i], batch.cameraRays[i]) : context.background();
  }
};

const bool registeredWavefront = registerWavefrontStage<WavefrontEyeLight>(stage1());

}  // namespace
}  // namespace pathway
