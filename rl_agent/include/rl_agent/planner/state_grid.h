/**
 * StateGrid: the original's state discretisation (DiscretizationAgent and the planners'
 * statesPerDim, ORIGINAL.md §1.3), written once for the agents and planners that bin states:
 *
 *   width = (max − min) / n,  bin = trunc((s + width/2) / width) if s > 0
 *                             else trunc((s − width/2) / width),  s' = width · bin
 *
 * i.e. rounding to the nearest multiple of `width`, anchored at 0 (not at min), as the
 * original. A feature with n = 0 or a zero range is not binned. trunc replaces the original's
 * cast to int, which is undefined for huge values; -0 comes out as +0, so equal bins hash alike.
 */
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

class StateGrid {
 public:
  /// No binning.
  StateGrid() = default;
  /// `binsPerFeature`: empty (no binning), one count for every feature, or one per feature.
  /// Throws std::invalid_argument for mismatched sizes or a negative count.
  StateGrid(const std::vector<int>& binsPerFeature, const std::vector<float>& featMin,
            const std::vector<float>& featMax);

  /// True if some feature is binned.
  bool bins() const { return bins_; }
  /// Number of features the grid was built for (0 without binning).
  std::size_t size() const { return width_.size(); }
  /// Bin width of feature j (0: not binned).
  float width(std::size_t j) const { return width_[j]; }

  /// Feature j's value binned.
  float bin(std::size_t j, float v) const {
    const float w = width_[j];
    if (!(w > 0.0f)) return v;
    const float b = v > 0.0f ? std::trunc((v + w / 2) / w) : std::trunc((v - w / 2) / w);
    return w * b + 0.0f;  // + 0.0f turns -0 into +0
  }
  /// `s` with its first size() features binned (any further ones, e.g. history, as they are).
  rl_common::State apply(const rl_common::State& s) const;

 private:
  std::vector<float> width_;
  bool bins_ = false;
};

}  // namespace rl_agent
