/**
 * PolicyIteration: alternates policy evaluation and greedy improvement (Howard 1960; Sutton &
 * Barto 2018, §4.3; the original's PolicyIteration, ORIGINAL.md §7.3, which used
 * maxSteps = 10):
 *
 *   evaluation   V(s) <- R(s,π(s)) + γ (1 − T) Σ_s' P(s'|s,π(s)) V(s')  in place, until the
 *                largest change is below the tolerance (at most 100000 sweeps);
 *   improvement  Q(s,a) from V; π(s) <- argmax_a Q(s,a), keeping π(s) unless another action
 *                is better by more than the tolerance,
 *
 * until the policy is stable. One iteration of the budget is one evaluation + improvement.
 * Here V(s') is max_a Q(s',a), which under a stable policy is V^π.
 */
#pragma once

#include <vector>

#include "rl_agent/planner/state_space_planner.h"

namespace rl_agent {

class PolicyIteration : public StateSpacePlanner {
 public:
  /// PolicyIteration with the original's maxSteps = 10 unless the config sets another.
  using StateSpacePlanner::StateSpacePlanner;
  /// Policy improvements in the last plan() call.
  long lastIterations() const { return lastIterations_; }

 protected:
  long solve(const rl_common::PlanningBudget& budget, const std::vector<int>& changed) override;

 private:
  std::vector<int> policy_;
  long lastIterations_ = 0;
};

}  // namespace rl_agent
