/**
 * ActionSelector: how an exploring model-based agent turns the planner's choice into the
 * action it takes (the original's --explore greedy, epsilongreedy, random; the paper's
 * Boltzmann comparison agent, TEXPLORE-VANIR paper §5.1):
 *
 *   greedy         the planner's greedy action
 *   epsilon-greedy a uniformly random action with probability ε, else the planner's
 *   random         a uniformly random action (the planner is not needed)
 *   Boltzmann      softmax of the planner's Q-values with temperature τ (BoltzmannSelector)
 *
 * Outside exploration (the paper's task phase) the agent acts greedily and does not ask.
 */
#pragma once

#include <vector>

#include "rl_agent/reward/explorer_registry.h"
#include "rl_common/random.h"

namespace rl_agent {

class ActionSelector {
 public:
  enum class Mode { Greedy, EpsilonGreedy, Random, Boltzmann };

  /// Throws std::invalid_argument for fewer than one action, ε outside [0, 1] or τ <= 0 with
  /// Boltzmann.
  ActionSelector(Mode mode, int numActions, double epsilon, double tau);
  /// The mode an explorer asks for (random before Boltzmann before ε-greedy).
  static ActionSelector forExplorer(const Explorer& explorer, int numActions, double epsilon);

  Mode mode() const { return mode_; }
  /// False when the planner's action is never used (random), so it need not be planned.
  bool needsPlanner() const { return mode_ != Mode::Random; }
  /// The action to take, from the planner's `plannerAction` and its Q-values `q` (Boltzmann
  /// keeps the planner's action when `q` has not one value per action).
  int choose(int plannerAction, const std::vector<double>& q, rl_common::Random& rng) const;

 private:
  Mode mode_;
  int numActions_;
  double epsilon_;
  double tau_;
};

}  // namespace rl_agent
