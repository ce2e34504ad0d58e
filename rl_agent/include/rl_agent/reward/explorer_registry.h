/**
 * The explorer registry: each --explore value names the intrinsic rewards a
 * model-based agent plans with (shared/spec/ORIGINAL.md §3.1, §5.5).
 *
 *   greedy           none: external reward only
 *   epsilongreedy    none, and the agent acts at random with probability
 * epsilon variancenovelty  TEXPLORE-VANIR: v * D(s,a) + n * delta(s,a) unknown
 * R-MAX-style: reward rmax and termination for (s,a) seen fewer than m times
 *   unvisitedstates  + n for states never visited
 *   unvisitedactions + n for state-actions never taken
 */
#pragma once

#include <memory>
#include <vector>

#include "rl_agent/reward/intrinsic_reward.h"
#include "rl_common/registry.h"

namespace rl_agent {

struct ExplorerSettings {
  float v = 0.0f;     ///< variance coefficient
  float n = 0.0f;     ///< novelty / unvisited bonus
  int m = 5;          ///< visits before a state-action is known
  float rmax = 1.0f;  ///< optimistic value for unknown state-actions
};

struct Explorer {
  std::vector<std::shared_ptr<const IntrinsicReward>> rewards;
  bool epsilonGreedy = false;
};

using ExplorerRegistry = rl_common::Registry<Explorer, const ExplorerSettings&>;

const ExplorerRegistry& explorerRegistry();

}  // namespace rl_agent
