/**
 * UnknownReward: R-MAX-style optimism (Brafman & Tennenholtz, "R-MAX", JMLR
 * 2002; the original's EXPLORE_UNKNOWN): a state-action visited fewer than m
 * times is predicted to end the episode with the value bound `rmax` (reward =
 * rmax, termProb = 1).
 */
#pragma once

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class UnknownReward : public IntrinsicReward {
 public:
  UnknownReward(int m, float rmax) : m_(m), rmax_(rmax) {}
  std::string name() const override { return "unknown"; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    if (c.visited.visits(c.input, c.action) >= m_) return;
    info->otherReward += rmax_ - info->reward;
    info->reward = rmax_;
    info->termProb = 1.0f;
  }

 private:
  int m_;
  float rmax_;
};

}  // namespace rl_agent
