// The render settings every command shares, each declared once as an option (render/parameters.h)
// with its default, range and help. The commands' CLI options, the viewer's widgets and the
// checks (where settings enter, and the Renderer's) are all made from these declarations.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "film/pixel_filter.h"
#include "render/parameters.h"
#include "sampling/sampler.h"

namespace pathway {

namespace setting {

inline const OptionSpec kWidth =
    OptionSpec::integer("width", 512, 1, 16384, "Image width in pixels");
inline const OptionSpec kHeight =
    OptionSpec::integer("height", 512, 1, 16384, "Image height in pixels");
inline const OptionSpec kSamplesPerPixel =
    OptionSpec::integer("spp", 16, 1, 1 << 20, "Samples per pixel");
inline const OptionSpec kSamplesPerPass = OptionSpec::integer(
    "spp-per-pass", 1, 1, kSamplesPerPixel.maxValue,
    "Samples added to every pixel per pass (the viewer shows an image after each)");
inline const OptionSpec kSeed =
    OptionSpec::integer("seed", 0, 0, 18446744073709551615.0, "Random seed; same seed, same image");
inline const OptionSpec kThreads =
    OptionSpec::integer("threads", 0, 0, 1024, "Worker threads (0: all cores)");
inline const OptionSpec kFilterRadius = OptionSpec::real(
    "filter-radius", 0.0, 0.0, kMaxFilterRadius,
    "Filter support in pixels (0: the filter's own, box 0.5, tent 1, mitchell 2, gaussian 1.5)");
inline const OptionSpec kExposure = OptionSpec::real(
    "exposure", 0.0, -20.0, 20.0, "Exposure in stops for PNG and display (EXR is never scaled)");
inline const OptionSpec kTileSize = OptionSpec::integer(
    "tile-size", 32, 4, 256, "Pixels per tile side (the unit of parallel work)");
// The viewer's "Make reference" (error plot): well beyond what the panes reach in a few seconds,
// so the reference's own noise stays below their error for most of the curve.
inline const OptionSpec kReferenceSamplesPerPixel = OptionSpec::integer(
    "reference-spp", 1024, 16, kSamplesPerPixel.maxValue,
    "Samples per pixel of the reference the viewer makes on demand (Make reference, key M)");
// The lecture's shrinking light (scene/resize_lights.h): a scene setting, but every command that
// loads a scene reads it.
inline const OptionSpec kLightScale = OptionSpec::real(
    "light-scale", 1.0, 0.01, 4.0,
    "Resize every light about its centre by this factor at fixed power (its radiance / factor^2)");
// The choices list their options in the order of the enums they stand for.
inline const OptionSpec kFilter =
    OptionSpec::choice("filter", "box", filterTypeNames(), "Pixel filter");
// No fixed default: each integrator declares the sampler it is meant to be seen with.
inline const OptionSpec kSampler =
    OptionSpec::choice("sampler", "independent", samplerTypeNames(), "Sampler");
inline const OptionSpec kEarlierStages = OptionSpec::choice(
    "earlier-stages", "own", {"own", "reference"},
    "Where the integrator's earlier stages come from (for your stage 3: 'own' is your stages "
    "1-2, 'reference' the reference's)");
// The integrator a render or the viewer starts with when none is named.
inline constexpr const char* kIntegrator = "stage1";

}  // namespace setting

// References render with seeds of their own, far above the seeds users pick and submissions are
// graded with (small numbers), so a reference never repeats the samples of the image it judges:
// the grader's replicate i takes kReferenceSeed + i, a chart's reference kReferenceSeed, the
// viewer's on-demand reference kReferenceSeed + the pane's seed.
inline constexpr uint64_t kReferenceSeed = 1000000;

// A render in this many passes keeps a progress bar moving; more would only add per-pass cost.
inline uint32_t samplesPerProgressPass(uint32_t samples) {
  return std::max(1u, samples / 16);
}

struct RenderSettings {
  int width = setting::kWidth.defaultAs<int>();
  int height = setting::kHeight.defaultAs<int>();
  uint32_t samplesPerPixel = setting::kSamplesPerPixel.defaultAs<uint32_t>();
  uint32_t samplesPerPass = setting::kSamplesPerPass.defaultAs<uint32_t>();
  SamplerType sampler = SamplerType::Independent;
  uint64_t seed = setting::kSeed.defaultAs<uint64_t>();
  int threads = setting::kThreads.defaultAs<int>();
  FilterType filter = setting::kFilter.defaultAs<FilterType>();
  float filterRadius = setting::kFilterRadius.defaultAs<float>();  // 0: the filter's natural radius
  int tileSize = setting::kTileSize.defaultAs<int>();
  // The sample indices this render draws: [sampleBegin, sampleEnd) of the `samplesPerPixel` a
  // whole render would draw (sampleEnd 0: all of them). Parts of one render over disjoint ranges
  // merge into that render's image (`pathway merge`).
  uint32_t sampleBegin = 0;
  uint32_t sampleEnd = 0;

  uint32_t firstSample() const { return sampleBegin; }
  uint32_t endSample() const { return sampleEnd == 0 ? samplesPerPixel : sampleEnd; }
  uint32_t samplesToRender() const { return endSample() - firstSample(); }

  // The filter's support in pixels, with 0 decoded to the filter's natural radius.
  float filterRadiusPixels() const {
    return filterRadius > 0.0f ? filterRadius : naturalFilterRadius(filter);
  }
  // Throws PathwayError naming the first setting outside its declared range. The Renderer calls
  // it, once, whichever way a render was asked for.
  void check() const;

  bool operator==(const RenderSettings& o) const;
  bool operator!=(const RenderSettings& o) const { return !(*this == o); }
};

}  // namespace pathway
