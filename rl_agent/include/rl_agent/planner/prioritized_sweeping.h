/**
 * PrioritizedSweeping: value updates ordered by how much they matter (Moore & Atkeson,
 * "Prioritized sweeping: reinforcement learning with less data and less time", Machine
 * Learning 13, 1993; the original's PrioritizedSweeping, ORIGINAL.md §7.3).
 *
 * States whose model predictions changed enter a queue with priority equal to their Bellman
 * residual |max_a backup(s,a) − V(s)|. The planner pops the highest-priority state, backs up
 * all its actions, and every predecessor p (with P(s|p,a) > 0) gets priority
 * max(priority(p), γ P(s|p,a) |ΔV(s)|) and enters the queue if that exceeds the tolerance.
 * It stops when the queue is empty or the budget (one iteration = one state backup, at most
 * 100000 per call) is spent. With the threshold ε the values are within about ε/(1−γ) of value
 * iteration's.
 */
#pragma once

#include <vector>

#include "rl_agent/planner/state_space_planner.h"

namespace rl_agent {

class PrioritizedSweeping : public StateSpacePlanner {
 public:
  using StateSpacePlanner::StateSpacePlanner;
  /// State backups in the last plan() call.
  long lastBackups() const { return lastBackups_; }

 protected:
  long solve(const rl_common::PlanningBudget& budget, const std::vector<int>& changed) override;

 private:
  struct Pred {
    int state;
    double p;
  };
  std::vector<std::vector<Pred>> preds_;
  std::vector<double> priority_;
  long lastBackups_ = 0;
};

}  // namespace rl_agent
