/**
 * ValueIteration: solves the model's Bellman optimality equation by repeated in-place
 * (Gauss-Seidel) sweeps over the planner's states (Bellman 1957; Sutton & Barto 2018, §4.4;
 * the original's ValueIteration, ORIGINAL.md §7.3):
 *
 *   for every expanded s and a:  Q(s,a) <- R(s,a) + γ (1 − T(s,a)) Σ_s' P(s'|s,a) max_a' Q(s',a')
 *
 * until the largest change in a sweep is below the tolerance (the original's MIN_ERROR 1e-4).
 * Each state's self-transition is solved exactly within the sweep (Gauss-Seidel value iteration
 * with the diagonal term moved to the left, Puterman 1994, §6.3.3):
 *
 *   V(s) <- max_a [R + γ(1 − T) Σ_{s'≠s} P V(s')] / (1 − γ(1 − T) P(s|s,a))
 *
 * the same fixed point as the plain backup, reached in far fewer sweeps where actions often
 * leave the state unchanged (docs/performance/profile.md §7); the original's plain sweep
 * converged there only at the rate γ P(s|s,a) a sweep.
 * One iteration of the budget is one sweep. States are those of StateSpacePlanner (within
 * maxSteps = 100 model steps of a visited state, as the original).
 */
#pragma once

#include "rl_agent/planner/state_space_planner.h"

namespace rl_agent {

class ValueIteration : public StateSpacePlanner {
 public:
  using StateSpacePlanner::StateSpacePlanner;
  /// Sweeps in the last plan() call.
  long lastSweeps() const { return lastSweeps_; }

 protected:
  long solve(const rl_common::PlanningBudget& budget, const std::vector<int>& changed) override;

 private:
  long lastSweeps_ = 0;
};

}  // namespace rl_agent
