/**
 * The planners' validity check of a predicted state (the original's ETUCT/ValueIteration
 * check, ORIGINAL.md §4.6): a learned model's relative predictions can leave the task's
 * declared feature ranges, and such a state is not real. Written once for UctPlanner and
 * StateSpacePlanner.
 */
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "rl_common/experience.h"

namespace rl_agent {

/// True if each of the first featMin.size() features of `s` lies in [min − eps, max + eps]
/// (a NaN does not); features beyond them (e.g. an action history) are not checked.
inline bool withinFeatureRanges(const rl_common::State& s, const std::vector<float>& featMin,
                                const std::vector<float>& featMax, float eps) {
  const std::size_t n = std::min({s.size(), featMin.size(), featMax.size()});
  for (std::size_t j = 0; j < n; ++j) {
    if (!(s[j] >= featMin[j] - eps && s[j] <= featMax[j] + eps)) return false;
  }
  return true;
}

}  // namespace rl_agent
