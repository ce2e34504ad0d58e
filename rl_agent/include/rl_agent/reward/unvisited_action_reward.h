/**
 * UnvisitedActionReward: bonus n for a state-action never taken (the original's
 * UNVISITED_ACT_BONUS, ORIGINAL.md §5.5).
 */
#pragma once

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class UnvisitedActionReward : public IntrinsicReward {
 public:
  explicit UnvisitedActionReward(float n) : n_(n) {}
  std::string name() const override { return "unvisitedaction"; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    if (c.visited.visits(c.input, c.action) > 0) return;
    info->otherReward += n_;
    info->reward += n_;
  }

 private:
  float n_;
};

}  // namespace rl_agent
