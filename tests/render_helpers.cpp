#include "render_helpers.h"

#include "engine/recipe_builder.h"
#include "scene/ray_tracer.h"

namespace pathway::test {

RenderResult render(const Scene& scene, const RenderSpec& spec) {
  const RayTracer tracer(scene);
  return runRender(tracer, RecipeBuilder(spec.integrator)
                               .params(spec.params)
                               .earlierStages(spec.earlierStages)
                               .size(spec.width, spec.height)
                               .spp(spec.spp)
                               .sampler(spec.sampler)
                               .seed(spec.seed)
                               .filter(FilterType::Box));
}

Estimate meanOverPixels(const RenderResult& result, int channel,
                        const std::function<bool(int, int)>& include) {
  const Image& color = result.images.color;
  const Image& variance = result.images.variance;
  double sum = 0.0, varianceSum = 0.0;
  size_t count = 0;
  for (int y = 0; y < color.height; ++y) {
    for (int x = 0; x < color.width; ++x) {
      if (include && !include(x, y)) continue;
      sum += color.at(x, y)[channel];
      varianceSum += variance.at(x, y)[channel];
      ++count;
    }
  }
  Estimate e;
  e.pixels = count;
  if (count == 0) return e;
  e.mean = sum / count;
  e.standardError = std::sqrt(varianceSum) / count;
  return e;
}

bool agree(const Estimate& a, const Estimate& b, double allowance) {
  const double se =
      std::sqrt(a.standardError * a.standardError + b.standardError * b.standardError);
  return std::fabs(a.mean - b.mean) <= kZBound * se + allowance;
}

bool agree(const Estimate& a, double expected, double allowance) {
  return std::fabs(a.mean - expected) <= kZBound * a.standardError + allowance;
}

}  // namespace pathway::test
