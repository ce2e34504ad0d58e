/**
 * NoveltyReward: VANIR's novelty bonus n * delta(s, a), delta the normalised L1
 * distance to the nearest state where a was taken (NoveltyIndex; paper §4.2,
 * ORIGINAL.md §5.3).
 *
 * With `perState`, the novelty is that of the state alone: delta(s) = min_a' delta(s, a'), the
 * distance to the nearest state where any action was taken. The original's per-action
 * distance is largest for the actions taken least, which in LightWorld are PICKUP and PRESS
 * away from the objects: self-loops that teach the model nothing after a few tries, and that
 * then draw about a sixth of VANIR's steps. Per state, a state already visited earns no
 * novelty whatever the action, so novelty rewards going to new states, and the variance bonus
 * is left to reward the actions the model is unsure of.
 */
#pragma once

#include <algorithm>

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class NoveltyReward : public IntrinsicReward {
 public:
  explicit NoveltyReward(double n, bool perState = false) : n_(n), perState_(perState) {}
  std::string name() const override { return "novelty"; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    double delta = perState_ ? 1.0 : c.visited.novelty(c.input, c.action);
    if (perState_) {
      for (int a = 0; a < c.visited.numActions() && delta > 0.0; ++a) {
        delta = std::min(delta, c.visited.novelty(c.input, a));
      }
    }
    if (delta <= 0.0) return;
    const float bonus = static_cast<float>(n_ * delta);
    info->noveltyReward += bonus;
    info->reward += bonus;
  }

 private:
  double n_;
  bool perState_;
};

}  // namespace rl_agent
