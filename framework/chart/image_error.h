// How far an image is from a reference: the error measures the convergence charts and the viewer's
// live plot share. relMSE divides each squared error by the reference value squared plus ε, so
// bright and dark regions count alike and black pixels do not divide by zero.
#pragma once

#include "film/film.h"

namespace pathway {

// ε of relMSE: below a reference value of about 0.1 the error counts as absolute, not relative.
inline constexpr double kRelMseEpsilon = 0.01;

struct ImageError {
  double relMse = 0.0;  // mean over pixels and channels of (x − r)² / (r² + ε)
  double mse = 0.0;     // mean over pixels and channels of (x − r)²
  double rmse() const;  // √mse, in the image's own units
};

// Throws PathwayError when the sizes differ or either image is empty.
ImageError imageError(const Image& image, const Image& reference);

}  // namespace pathway
