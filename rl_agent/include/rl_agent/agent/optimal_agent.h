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
#include <string>

#include "rl_agent/model/true_model_view.h"
#include "rl_agent/planner/value_iteration.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"

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

/// Where a task description received from elsewhere (e.g. the env node's RLEnvDescription)
/// disagrees with the description of the environment whose true model the agent plans on:
/// number of actions, number of features, each feature's range, the reward range, episodic
/// and stochastic. Empty if they agree; otherwise one clause per difference, e.g.
/// "3 actions, the model has 4; feature 2 range [0, 1], the model's [0, 2]".
std::string trueModelMismatch(const rl_common::EnvironmentDescription& model,
                              const rl_common::EnvironmentDescription& received);

}  // namespace rl_agent
