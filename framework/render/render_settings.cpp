#include "render/render_settings.h"

#include "core/error.h"

namespace pathway {
namespace {

void require(const OptionSpec& spec, double value) {
  if (!spec.accepts(value))
    throw PathwayError(spec.name + " must be in " + spec.describeRange() + ", got " +
                       spec.format(value));
}

}  // namespace

void RenderSettings::check() const {
  require(setting::kWidth, width);
  require(setting::kHeight, height);
  require(setting::kSamplesPerPixel, samplesPerPixel);
  require(setting::kSamplesPerPass, samplesPerPass);
  require(setting::kThreads, threads);
  require(setting::kFilterRadius, filterRadius);
  require(setting::kTileSize, tileSize);
  if (endSample() > samplesPerPixel || firstSample() >= endSample())
    throw PathwayError("the sample range " + std::to_string(firstSample()) + ":" +
                       std::to_string(endSample()) + " must be a non-empty part of [0, " +
                       std::to_string(samplesPerPixel) + ") (the render's spp)");
}

bool RenderSettings::operator==(const RenderSettings& o) const {
  return width == o.width && height == o.height && samplesPerPixel == o.samplesPerPixel &&
         samplesPerPass == o.samplesPerPass && sampler == o.sampler && seed == o.seed &&
         threads == o.threads && filter == o.filter && filterRadius == o.filterRadius &&
         tileSize == o.tileSize && firstSample() == o.firstSample() && endSample() == o.endSample();
}

}  // namespace pathway
