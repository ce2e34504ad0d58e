#include "rl_agent/planner/state_grid.h"

#include <stdexcept>
#include <string>

namespace rl_agent {

StateGrid::StateGrid(const std::vector<int>& binsPerFeature, const std::vector<float>& featMin,
                     const std::vector<float>& featMax) {
  if (binsPerFeature.empty()) return;
  const std::size_t d = featMin.size();
  if (d == 0 || featMax.size() != d || (binsPerFeature.size() != 1 && binsPerFeature.size() != d)) {
    throw std::invalid_argument(
        "StateGrid::StateGrid(): need feature ranges and one bin count, "
        "or one per feature (got " +
        std::to_string(binsPerFeature.size()) + " for " + std::to_string(d) + " features)");
  }
  width_.assign(d, 0.0f);
  for (std::size_t j = 0; j < d; ++j) {
    const int n = binsPerFeature.size() == 1 ? binsPerFeature[0] : binsPerFeature[j];
    if (n < 0) {
      throw std::invalid_argument("StateGrid::StateGrid(): bin counts must be >= 0 (got " +
                                  std::to_string(n) + ")");
    }
    if (n > 0) width_[j] = (featMax[j] - featMin[j]) / static_cast<float>(n);
    bins_ |= width_[j] > 0.0f;
  }
}

rl_common::State StateGrid::apply(const rl_common::State& s) const {
  if (!bins_) return s;
  rl_common::State out(s);
  for (std::size_t j = 0; j < width_.size() && j < s.size(); ++j) out[j] = bin(j, s[j]);
  return out;
}

}  // namespace rl_agent
