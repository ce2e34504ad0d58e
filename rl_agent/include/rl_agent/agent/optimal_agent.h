/**
 * OptimalAgent: the reference "optimal policy" of the paper's figures (TEXPLORE-VANIR paper
 * §5.1: "an optimal policy (with full a priori knowledge of the transition and reward
 * functions)"): it plans by value iteration on the environment's true model
 * (rl_common::TrueModel, through TrueModelView) and acts greedily.
 *
 * At construction every reachable state of the model is a root, so value iteration solves the
 * whole task once (tolerance 1e-6); a state met later that was not listed is added and the
 * values are brought up to date. It does not learn. Ties are broken at random (seeded).
 * The true model must outlive the agent.
 */
#pragma once

#include <cstdint>
#include <memory>

#include "rl_agent/model/true_model_view.h"
#include "rl_agent/planner/value_iteration.h"
#include "rl_common/agent.h"

namespace rl_agent {

class OptimalAgent : public rl_common::Agent {
 public:
  struct Config {
    int numActions = 0;
    double gamma = 0.99;
    double tolerance = 1e-6;
  };

  /// Solves the task. Throws std::invalid_argument for a bad configuration.
  OptimalAgent(const Config& config, const rl_common::TrueModel& model, std::uint64_t seed);

  int firstAction(const rl_common::State& s) override { return act(s); }
  int nextAction(float /*reward*/, const rl_common::State& s) override { return act(s); }
  void lastAction(float /*reward*/) override {}

  /// V*(s) = max_a Q*(s, a) (for a state the agent has planned).
  double value(const rl_common::State& s) const { return planner_.value(s); }
  std::vector<double> qValues(const rl_common::State& s) const { return planner_.qValues(s); }
  std::size_t numStates() const { return planner_.numStates(); }

 private:
  int act(const rl_common::State& s);
  static StateSpacePlanner::Config plannerConfig(const Config& c);

  std::shared_ptr<const TrueModelView> view_;
  ValueIteration planner_;
};

}  // namespace rl_agent
