/**
 * RewardBreakdownSource: implemented by agents with intrinsic rewards, so that logs and the
 * agent node can show what drives the agent (the parts of the reward its model predicted for
 * the action it last chose).
 */
#pragma once

#include <limits>

namespace rl_agent {

struct RewardBreakdown {
  float variance = 0.0f;
  float novelty = 0.0f;
  float other = 0.0f;
  /// The planner's value Q(s, a) of the chosen action (the return it expected, intrinsic
  /// rewards included) and max_a Q − min_a Q at s; NaN when the planner has none.
  double plannedValue = std::numeric_limits<double>::quiet_NaN();
  double valueSpread = std::numeric_limits<double>::quiet_NaN();
};

class RewardBreakdownSource {
 public:
  virtual ~RewardBreakdownSource() = default;
  /// The intrinsic parts predicted for the most recent action.
  virtual RewardBreakdown lastRewardBreakdown() const = 0;
};

}  // namespace rl_agent
