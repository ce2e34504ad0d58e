/**
 * RewardBreakdownSource: implemented by agents with intrinsic rewards, so that logs and the
 * agent node can show what drives the agent (the parts of the reward its model predicted for
 * the action it last chose).
 */
#pragma once

namespace rl_agent {

struct RewardBreakdown {
  float variance = 0.0f;
  float novelty = 0.0f;
  float other = 0.0f;
};

class RewardBreakdownSource {
 public:
  virtual ~RewardBreakdownSource() = default;
  /// The intrinsic parts predicted for the most recent action.
  virtual RewardBreakdown lastRewardBreakdown() const = 0;
};

}  // namespace rl_agent
