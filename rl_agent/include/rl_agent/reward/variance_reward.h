/**
 * VarianceReward: VANIR's model-disagreement bonus v * D(s, a), where D is the
 * random forests' mean pairwise KL divergence / ln 100 averaged over the
 * model's outputs (FactoredModel::View::variance; paper §4.2, ORIGINAL.md
 * §5.2).
 */
#pragma once

#include "rl_agent/reward/intrinsic_reward.h"

namespace rl_agent {

class VarianceReward : public IntrinsicReward {
 public:
  explicit VarianceReward(double v) : v_(v) {}
  std::string name() const override { return "variance"; }
  bool usesVariance() const override { return true; }
  void apply(const BonusContext& c, rl_common::StateActionInfo* info) const override {
    const double d = c.variance != nullptr ? *c.variance : c.model.variance(c.input, c.action);
    if (d <= 0.0) return;
    const float bonus = static_cast<float>(v_ * d);
    info->varianceReward += bonus;
    info->reward += bonus;
  }

 private:
  double v_;
};

}  // namespace rl_agent
