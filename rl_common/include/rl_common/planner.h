/**
 * Planner: computes action values on a model (a ModelView) under an explicit budget.
 *
 * setModel() hands the planner a new model view (a new model version); plan() searches from a
 * state until its budget (rollouts and/or a deadline) is spent; bestAction() returns the
 * greedy action for a state. Budgets are explicit so that tests and reproducible experiments
 * spend a fixed number of rollouts and the real-time agent a deadline.
 */
#pragma once

#include <chrono>
#include <memory>
#include <vector>

#include "rl_common/experience.h"
#include "rl_common/mdp_model.h"

namespace rl_common {

/// How much planning to do: stop after `rollouts` rollouts (0: no limit) or at `deadline`
/// (time_point::max(): none), whichever comes first. At least one rollout always runs.
struct PlanningBudget {
  long rollouts = 0;
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();

  static PlanningBudget ofRollouts(long n) {
    PlanningBudget b;
    b.rollouts = n;
    return b;
  }
  static PlanningBudget until(std::chrono::steady_clock::time_point t) {
    PlanningBudget b;
    b.deadline = t;
    return b;
  }
};

class Planner {
 public:
  virtual ~Planner() = default;
  /// Plans on `model` from now on (a new model version).
  virtual void setModel(std::shared_ptr<const ModelView> model) = 0;
  /// Searches from state `s` within `budget`; returns the number of rollouts done.
  virtual long plan(const State& s, const PlanningBudget& budget) = 0;
  /// The greedy action in `s` (random tie-break among near-equal values).
  virtual int bestAction(const State& s) = 0;
  /// The action values in `s` (empty if the planner has none for it, or keeps none). Root-
  /// parallel search combines its trees' values with it.
  virtual std::vector<double> qValues(const State& /*s*/) const { return {}; }
};

}  // namespace rl_common
