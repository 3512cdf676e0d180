// Picks an index with probability proportional to a weight (e.g. an emitter by its power),
// by inverting the cumulative distribution with a binary search.
#pragma once

#include <cstddef>
#include <vector>

namespace pathway {

class DiscreteDistribution {
 public:
  DiscreteDistribution() = default;
  // Negative and non-finite weights count as 0. All zero: the distribution is empty.
  explicit DiscreteDistribution(const std::vector<double>& weights);

  bool empty() const { return total_ <= 0.0; }
  size_t size() const { return cdf_.size(); }
  // The index whose CDF interval holds u in [0, 1); never an index of weight 0.
  size_t sample(float u) const;
  // Probability of picking `index`.
  float probability(size_t index) const;

 private:
  std::vector<double> cdf_;  // cdf_[i] = (w_0 + ... + w_i) / total
  double total_ = 0.0;
};

}  // namespace pathway
