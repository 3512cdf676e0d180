#include "chart/image_error.h"

#include <cmath>

#include "core/error.h"

namespace pathway {

double ImageError::rmse() const {
  return std::sqrt(mse);
}

ImageError imageError(const Image& image, const Image& reference) {
  if (image.pixels.empty() || reference.pixels.empty())
    throw PathwayError("cannot measure the error of an empty image");
  if (image.width != reference.width || image.height != reference.height)
    throw PathwayError("the image is " + std::to_string(image.width) + "x" +
                       std::to_string(image.height) + " but the reference is " +
                       std::to_string(reference.width) + "x" + std::to_string(reference.height));
  double relative = 0.0, absolute = 0.0;
  for (size_t i = 0; i < image.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double r = reference.pixels[i][c];
      const double d = double(image.pixels[i][c]) - r;
      relative += d * d / (r * r + kRelMseEpsilon);
      absolute += d * d;
    }
  }
  const double count = 3.0 * double(image.pixels.size());
  return {relative / count, absolute / count};
}

}  // namespace pathway
