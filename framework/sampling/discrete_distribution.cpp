#include "sampling/discrete_distribution.h"

#include <algorithm>
#include <cmath>

namespace pathway {

DiscreteDistribution::DiscreteDistribution(const std::vector<double>& weights) {
  cdf_.reserve(weights.size());
  double sum = 0.0;
  for (double w : weights) {
    sum += (std::isfinite(w) && w > 0.0) ? w : 0.0;
    cdf_.push_back(sum);
  }
  total_ = sum;
  if (total_ > 0.0)
    for (double& c : cdf_) c /= total_;
}

size_t DiscreteDistribution::sample(float u) const {
  // First entry whose cumulative value exceeds u: zero-weight entries have an empty interval.
  const auto it = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
  return std::min(static_cast<size_t>(it - cdf_.begin()), cdf_.size() - 1);
}

float DiscreteDistribution::probability(size_t index) const {
  if (total_ <= 0.0 || index >= cdf_.size()) return 0.0f;
  return static_cast<float>(cdf_[index] - (index > 0 ? cdf_[index - 1] : 0.0));
}

}  // namespace pathway
