/**
 * UnvisitedStateReward: bonus n for a state never visited with any action (the
 * original's UNVISITED_BONUS, ORIGINAL.md §5.5; there its n could not be set
 * from the command line).
 */
#pragma once

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class UnvisitedStateReward : public IntrinsicReward {
 public:
  explicit UnvisitedStateReward(float n) : n_(n) {}
  std::string name() const override { return "unvisitedstate"; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    if (c.visited.stateVisited(c.input)) return;
    info->otherReward += n_;
    info->reward += n_;
  }

 private:
  float n_;
};

}  // namespace rl_agent
