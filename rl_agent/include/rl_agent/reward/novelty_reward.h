/**
 * NoveltyReward: VANIR's novelty bonus n * delta(s, a), delta the normalised L1
 * distance to the nearest state where a was taken (NoveltyIndex; paper §4.2,
 * ORIGINAL.md §5.3).
 */
#pragma once

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class NoveltyReward : public IntrinsicReward {
 public:
  explicit NoveltyReward(double n) : n_(n) {}
  std::string name() const override { return "novelty"; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    const double delta = c.visited.novelty(c.input, c.action);
    if (delta <= 0.0) return;
    const float bonus = static_cast<float>(n_ * delta);
    info->noveltyReward += bonus;
    info->reward += bonus;
  }

 private:
  double n_;
};

}  // namespace rl_agent
