/**
 * DiscretizationAgent: wraps another agent and bins every state feature before the inner
 * agent sees it (the original's DiscretizationAgent, `--nstates`, ORIGINAL.md §1.3), on the
 * StateGrid (state_grid.h): rounding to the nearest multiple of (max − min) / n, anchored at 0.
 * A feature with n = 0 or a zero range stays continuous. Seed experiences are binned the same
 * way. The wrapper forwards savePolicy and the reward breakdown.
 */
#pragma once

#include <memory>
#include <vector>

#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_agent/planner/state_grid.h"
#include "rl_common/agent.h"

namespace rl_agent {

class DiscretizationAgent : public rl_common::Agent, public RewardBreakdownSource {
 public:
  /// `statesPerDim`: one entry for every feature, or one per feature. Throws
  /// std::invalid_argument for a null agent, mismatched sizes or a negative bin count.
  DiscretizationAgent(std::unique_ptr<rl_common::Agent> inner, std::vector<int> statesPerDim,
                      std::vector<float> featMin, std::vector<float> featMax);

  int firstAction(const rl_common::State& s) override;
  int nextAction(float reward, const rl_common::State& s) override;
  void lastAction(float reward) override { inner_->lastAction(reward); }
  void seedExperiences(const std::vector<rl_common::Experience>& seeds) override;
  void savePolicy(const std::string& filename) override { inner_->savePolicy(filename); }
  RewardBreakdown lastRewardBreakdown() const override;

  /// `s` binned as above.
  rl_common::State discretize(const rl_common::State& s) const;
  rl_common::Agent& inner() { return *inner_; }

 private:
  std::unique_ptr<rl_common::Agent> inner_;
  StateGrid grid_;
};

}  // namespace rl_agent
