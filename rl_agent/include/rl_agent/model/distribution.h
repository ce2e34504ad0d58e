/**
 * Distribution: a discrete distribution over float outcomes, the output of every classifier
 * of the suite (a tree leaf, a forest, a factored model's per-feature prediction).
 */
#pragma once

#include <utility>
#include <vector>

namespace rl_agent {

/// (value, probability) pairs sorted by value, probabilities summing to 1; empty = no data.
using Distribution = std::vector<std::pair<float, double>>;

/// Probability of `value` (0 if absent).
inline double probabilityOf(const Distribution& d, float value) {
  for (const auto& [v, p] : d) {
    if (v == value) return p;
  }
  return 0.0;
}

/// Expected value; 0 for an empty distribution.
inline double expectation(const Distribution& d) {
  double e = 0.0;
  for (const auto& [v, p] : d) e += v * p;
  return e;
}

}  // namespace rl_agent
