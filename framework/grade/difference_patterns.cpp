#include "grade/difference_patterns.h"

#include "grade/difference_diagnosis.h"
#include "grade/image_comparison.h"
#include "scene/camera.h"
#include "stages/stage_catalog.h"

namespace pathway {
namespace {

// The patterns only need to be clearer than one submission's render: this many times its samples.
constexpr uint32_t kPatternSppFactor = 8;
// Emitters (emissive materials) whose direct light is stored apart, at most.
constexpr size_t kMostEmittersApart = 4;
// Camera rays per pixel side for the escaped share.
constexpr int kEscapeRaysPerSide = 4;
// Seeds of the pattern renders: apart from the replicates' (kReferenceSeed + i).
constexpr uint64_t kPatternSeed = kReferenceSeed + 500000;
// Seeds of the background, deeper-path and half-pixel-move patterns: apart from the per-emitter
// ones above.
constexpr uint64_t kLaterPatternSeed = kPatternSeed + 1000;

Image renderVariant(const GradingCase& gradingCase, const RayTracer& tracer,
                    ReferenceTracing tracing, const std::map<std::string, std::string>& params,
                    uint64_t seed, Vec2 imageMoved = Vec2(0.0f)) {
  GradingCase variant = gradingCase;
  for (const auto& [name, value] : params) variant.params[name] = value;
  variant.spp *= kPatternSppFactor;
  const Camera camera =
      Camera(tracer.scene(), variant.width, variant.height).withImageMoved(imageMoved);
  return runRender(tracer, camera,
                   variant.recipe(Variant::Reference, EarlierStages::Own, seed, tracing))
      .images.color;
}

Image difference(const Image& a, const Image& b) {
  return sumOfImages(a, &b, -1.0f);
}

bool isZero(const Image& image) {
  for (const Color& c : image.pixels)
    if (c.x != 0.0f || c.y != 0.0f || c.z != 0.0f) return false;
  return true;
}

Image escapedBackground(const GradingCase& gradingCase, const RayTracer& tracer) {
  const Camera camera(tracer.scene(), gradingCase.width, gradingCase.height);
  RayCounters counters;
  Image result(gradingCase.width, gradingCase.height);
  const float share = 1.0f / (kEscapeRaysPerSide * kEscapeRaysPerSide);
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x)
      for (int j = 0; j < kEscapeRaysPerSide; ++j)
        for (int i = 0; i < kEscapeRaysPerSide; ++i) {
          const Vec2 film(x + (i + 0.5f) / kEscapeRaysPerSide, y + (j + 0.5f) / kEscapeRaysPerSide);
          if (!tracer.intersect(camera.generateRay(film), RayKind::Primary, counters))
            result.at(x, y) += share * tracer.scene().background;
        }
  return result;
}

// Every tile's pixels replaced by the tile's mean: how the patterns are stored.
Image tileAveraged(const Image& image, int tileSize) {
  return constantOverTiles(image.width, image.height, tileSize,
                           [&](const TileBounds& t) { return tileMean(image, t); });
}

}  // namespace

Image sumOfImages(const Image& a, const Image* b, float sign) {
  Image result = a;
  if (b)
    for (size_t p = 0; p < result.pixels.size(); ++p) result.pixels[p] += sign * b->pixels[p];
  return result;
}

std::map<std::string, Image> makeDifferencePatterns(const GradingCase& gradingCase,
                                                    const RayTracer& tracer,
                                                    const Image& referenceMean,
                                                    const Image& renderVariance,
                                                    ReferenceTracing tracing) {
  std::map<std::string, Image> patterns;
  if (!renderVariance.pixels.empty()) patterns[pattern::kRenderVariance] = renderVariance;
  patterns[pattern::kEscaped] = escapedBackground(gradingCase, tracer);
  const uint64_t seed = kPatternSeed;
  // What to vary comes from the stage's declared parameters (render/parameters.h, OptionRole).
  const std::vector<OptionSpec>& declared = stageInfo(gradingCase.stage).params;
  const OptionSpec* reach = optionWithRole(declared, OptionRole::AoReach);
  const OptionSpec* depth = optionWithRole(declared, OptionRole::RecursionDepth);
  const OptionSpec* nee = optionWithRole(declared, OptionRole::NextEventEstimation);
  const ParamValues values =
      gradingCase.recipe(Variant::Reference, EarlierStages::Own, seed).params;
  if (reach) {
    // The shortest reach there is: nothing blocks such a ray, so this is the image without
    // occlusion (1 on every surface, the background elsewhere).
    const Image unoccluded = renderVariant(gradingCase, tracer, tracing,
                                           {{reach->name, reach->format(reach->minValue)}}, seed);
    patterns[pattern::kOccluded] = difference(unoccluded, referenceMean);
    // The same AO with longer rays: how the image changes when the reach is misread.
    const double d = values.number(reach->name);
    if (d < 0.1 * reach->maxValue) {
      patterns[pattern::kLongerRays] =
          difference(renderVariant(gradingCase, tracer, tracing,
                                   {{reach->name, reach->format(2.0 * d)}}, seed + 1),
                     referenceMean);
      patterns[pattern::kUnlimitedRays] =
          difference(renderVariant(gradingCase, tracer, tracing,
                                   {{reach->name, reach->format(reach->maxValue)}}, seed + 2),
                     referenceMean);
    }
  } else if (depth) {
    std::map<std::string, std::string> emitted = {{depth->name, depth->format(0)}},
                                       direct = {{depth->name, depth->format(1)}};
    // NEE leaves the expected image as it is and makes these two far less noisy.
    if (nee) emitted[nee->name] = direct[nee->name] = nee->format(1);
    const Image m0 = renderVariant(gradingCase, tracer, tracing, emitted, seed);
    const Image m1 = renderVariant(gradingCase, tracer, tracing, direct, seed + 1);
    patterns[pattern::kDirect] = difference(m1, m0);
    if (values.number(depth->name) != 1)
      patterns[pattern::kIndirect] = difference(referenceMean, m1);
    // One bounce deeper than the case asks: a depth test off by one adds this (and one that
    // stops a bounce early takes away about what it adds one bounce on).
    const double asked = values.number(depth->name);
    if (asked >= 1.0 && asked + 1.0 <= depth->maxValue)
      patterns[pattern::kOneBounceMore] =
          difference(renderVariant(gradingCase, tracer, tracing,
                                   {{depth->name, depth->format(asked + 1.0)}}, kLaterPatternSeed),
                     referenceMean);
    std::vector<size_t> emissive;
    for (size_t m = 0; m < tracer.scene().materials.size(); ++m)
      if (tracer.scene().materials[m].isEmissive()) emissive.push_back(m);
    // The background's light on surfaces: every emitter dark, minus what the camera sees of the
    // background itself. What a bounce ray that leaves the scene returns, and its weight, act here.
    const Color background = tracer.scene().background;
    if (background.x > 0.0f || background.y > 0.0f || background.z > 0.0f) {
      Scene dark = tracer.scene();
      for (size_t m : emissive) dark.materials[m].emission = Color(0.0f);
      const RayTracer darkTracer(dark);
      const Image seen =
          renderVariant(gradingCase, darkTracer, tracing, emitted, kLaterPatternSeed + 2);
      patterns[pattern::kSkyLit] = difference(
          renderVariant(gradingCase, darkTracer, tracing, {}, kLaterPatternSeed + 1), seen);
      patterns[pattern::kSkyLitOnce] = difference(
          renderVariant(gradingCase, darkTracer, tracing, direct, kLaterPatternSeed + 12), seen);
    }
    // Each emitter's direct light on its own (the others dark), where there are several: a pdf
    // that does not match the picking rule is off by a factor of each emitter's own.
    if (emissive.size() >= 2 && emissive.size() <= kMostEmittersApart) {
      for (size_t k = 0; k < emissive.size(); ++k) {
        Scene alone = tracer.scene();
        for (size_t other : emissive)
          if (other != emissive[k]) alone.materials[other].emission = Color(0.0f);
        const RayTracer aloneTracer(alone);
        const uint64_t seeds = seed + 2 + 3 * k;
        const Image emittedAlone = renderVariant(gradingCase, aloneTracer, tracing, emitted, seeds);
        patterns[pattern::directFrom(k)] = difference(
            renderVariant(gradingCase, aloneTracer, tracing, direct, seeds + 1), emittedAlone);
        patterns[pattern::litFrom(k)] = difference(
            renderVariant(gradingCase, aloneTracer, tracing, {}, seeds + 2), emittedAlone);
      }
    }
  } else {
    // A stage with neither (stage 1) is seen through its pixel filter.
    // Central differences half a pixel each way: the image moved by one pixel, to first order,
    // at the scale where filters act (a pixel-level gradient misreads fine stripes).
    const float half = 0.5f;
    patterns[pattern::kMovedRight] =
        difference(renderVariant(gradingCase, tracer, tracing, {}, seed, Vec2(half, 0.0f)),
                   renderVariant(gradingCase, tracer, tracing, {}, seed + 1, Vec2(-half, 0.0f)));
    patterns[pattern::kMovedDown] =
        difference(renderVariant(gradingCase, tracer, tracing, {}, seed + 2, Vec2(0.0f, half)),
                   renderVariant(gradingCase, tracer, tracing, {}, seed + 3, Vec2(0.0f, -half)));
    // Half-pixel moves each way, rendered: the pixel-centre and pixel-range mistakes move the
    // image by just that, and a move of fine stripes is not their interpolation.
    for (int j = -1; j <= 1; ++j)
      for (int i = -1; i <= 1; ++i)
        if (i != 0 || j != 0)
          patterns[pattern::movedByHalves(i, j)] = difference(
              renderVariant(gradingCase, tracer, tracing, {},
                            kLaterPatternSeed + 3 * (j + 1) + i + 1, Vec2(half * i, half * j)),
              referenceMean);
    // The filter a quarter wider minus a fifth narrower: its support, to first order in ln r.
    const float radius = gradingCase.filterRadius > 0.0f ? gradingCase.filterRadius
                                                         : naturalFilterRadius(gradingCase.filter);
    GradingCase wider = gradingCase, narrower = gradingCase;
    wider.filterRadius = 1.25f * radius;
    narrower.filterRadius = 0.8f * radius;
    patterns[pattern::kWiderFilter] =
        difference(renderVariant(wider, tracer, tracing, {}, seed + 4),
                   renderVariant(narrower, tracer, tracing, {}, seed + 5));
  }
  for (auto it = patterns.begin(); it != patterns.end();)
    it = isZero(it->second) ? patterns.erase(it) : std::next(it);
  // The diagnosis reads patterns tile by tile: stored as tile means, they cost the reference
  // file next to nothing (ZIP shrinks constant runs), where noisy pixels would double it.
  for (auto& [name, image] : patterns) image = tileAveraged(image, gradingCase.tileSize);
  return patterns;
}

}  // namespace pathway
