/**
 * RandomRegions: a random partition of the state space into regions, fixed at the start, for
 * the R-IAC-style comparison explorers (Baranes & Oudeyer, "R-IAC: Robust Intrinsically
 * Motivated Exploration and Active Learning", IEEE Trans. Autonomous Mental Development 1(3),
 * 2009; TEXPLORE-VANIR paper §5.1: "splits the state space into random regions at the start").
 *
 * Built as a random k-d partition of the declared feature box: starting from the whole box,
 * `count − 1` times a leaf box is chosen uniformly, then a feature with a non-zero width in it
 * uniformly, and the box is cut at a uniform threshold on that feature. Regions are the leaves,
 * numbered 0 .. count−1. A state's region is found by descending the cuts (x <= threshold:
 * lower side); features beyond the declared ones (history) are ignored. Immutable after
 * construction.
 */
#pragma once

#include <cstdint>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

class RandomRegions {
 public:
  /// Throws std::invalid_argument for empty or mismatched ranges or count < 1.
  RandomRegions(const std::vector<float>& featMin, const std::vector<float>& featMax, int count,
                std::uint64_t seed);

  /// The region of `s` (its first featMin.size() features), in [0, size()).
  int regionOf(const rl_common::State& s) const;
  int size() const { return count_; }

  struct Cut {
    int feature = -1;  ///< -1: a leaf
    float threshold = 0.0f;
    int lower = -1, upper = -1;  ///< child cuts
    int region = -1;             ///< leaf: its region
  };
  const std::vector<Cut>& cuts() const { return cuts_; }

 private:
  std::size_t numFeatures_;
  int count_ = 0;
  std::vector<Cut> cuts_;  ///< cuts_[0] is the root
};

}  // namespace rl_agent
