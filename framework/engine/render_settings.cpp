#include "engine/render_settings.h"

#include "core/error.h"

namespace pathway {

void RenderSettings::check() const {
  setting::kWidth.require(width);
  setting::kHeight.require(height);
  setting::kSamplesPerPixel.require(samplesPerPixel);
  setting::kSamplesPerPass.require(samplesPerPass);
  setting::kThreads.require(threads);
  setting::kFilterRadius.require(filterRadius);
  setting::kTileSize.require(tileSize);
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
