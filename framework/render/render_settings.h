// The render settings every command shares, each declared once with its default, range and help.
// `pathway render`, `pathway view` (options and panel widgets), the renderer's own checks and the
// EXR metadata all read these declarations.
#pragma once

#include <cstdint>
#include <limits>
#include <string>

#include "film/pixel_filter.h"
#include "sampling/sampler.h"

namespace pathway {

template <typename T>
struct SettingSpec {
  const char* name;  // the command-line option, without "--"
  T defaultValue;
  T minValue;
  T maxValue;
  const char* help;

  bool accepts(T value) const { return value >= minValue && value <= maxValue; }
};

namespace setting {

inline constexpr SettingSpec<int> kWidth{"width", 512, 1, 16384, "Image width in pixels"};
inline constexpr SettingSpec<int> kHeight{
    "height", 512, 1, 16384, "Image height in pixels (default: from the camera's aspect ratio)"};
inline constexpr SettingSpec<uint32_t> kSamplesPerPixel{"spp", 16, 1, 1u << 20,
                                                        "Samples per pixel"};
// The viewer refines progressively, so it aims higher; same range.
inline constexpr SettingSpec<uint32_t> kViewerSamplesPerPixel{
    "spp", 4096, kSamplesPerPixel.minValue, kSamplesPerPixel.maxValue,
    "Samples per pixel at which rendering stops"};
// The viewer's "Make reference" (error plot): well beyond what the panes reach in a few seconds,
// so the reference's own noise stays below their error for most of the curve.
inline constexpr SettingSpec<uint32_t> kReferenceSamplesPerPixel{
    "reference-spp", 1024, 16, kSamplesPerPixel.maxValue,
    "Samples per pixel of the reference the viewer makes on demand (Make reference, key M)"};
inline constexpr SettingSpec<uint32_t> kSamplesPerPass{
    "spp-per-pass", 1, 1, kSamplesPerPixel.maxValue,
    "Samples added to every pixel per pass (the viewer shows an image after each)"};
inline constexpr SettingSpec<uint64_t> kSeed{"seed", 0, 0, std::numeric_limits<uint64_t>::max(),
                                             "Random seed; same seed, same image"};
inline constexpr SettingSpec<int> kThreads{"threads", 0, 0, 1024, "Worker threads (0: all cores)"};
inline constexpr SettingSpec<float> kFilterRadius{
    "filter-radius", 0.0f, 0.0f, kMaxFilterRadius,
    "Filter support in pixels (0: the filter's own, box 0.5, tent 1, mitchell 2, gaussian 1.5)"};
inline constexpr SettingSpec<float> kExposure{"exposure", 0.0f, -20.0f, 20.0f,
                                              "Exposure in stops for PNG and display (EXR is "
                                              "never scaled)"};
inline constexpr SettingSpec<int> kTileSize{"tile-size", 32, 4, 256,
                                            "Pixels per tile side (the unit of parallel work)"};
inline constexpr FilterType kFilter = FilterType::Box;
// The sampler has no fixed default: each integrator declares the one it is meant to be seen with.

}  // namespace setting

struct RenderSettings {
  int width = setting::kWidth.defaultValue;
  int height = setting::kHeight.defaultValue;
  uint32_t samplesPerPixel = setting::kSamplesPerPixel.defaultValue;
  uint32_t samplesPerPass = setting::kSamplesPerPass.defaultValue;
  SamplerType sampler = SamplerType::Independent;
  uint64_t seed = setting::kSeed.defaultValue;
  int threads = setting::kThreads.defaultValue;
  FilterType filter = setting::kFilter;
  float filterRadius = setting::kFilterRadius.defaultValue;  // 0: the filter's natural radius
  int tileSize = setting::kTileSize.defaultValue;
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
  // Throws PathwayError naming the first setting outside its declared range.
  void check() const;

  bool operator==(const RenderSettings& o) const;
  bool operator!=(const RenderSettings& o) const { return !(*this == o); }
};

}  // namespace pathway
