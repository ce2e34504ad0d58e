#include "rl_agent/agent/optimal_agent.h"

#include <limits>
#include <stdexcept>

namespace rl_agent {

StateSpacePlanner::Config OptimalAgent::plannerConfig(const Config& c) {
  StateSpacePlanner::Config pc;
  pc.numActions = c.numActions;
  pc.gamma = c.gamma;
  pc.tolerance = c.tolerance;
  pc.maxSteps = std::numeric_limits<int>::max() - 2;  // the whole reachable space
  pc.maxIterations = 1000000;
  return pc;
}

OptimalAgent::OptimalAgent(const Config& config, const rl_common::TrueModel& model,
                           std::uint64_t seed)
    : view_(std::make_shared<TrueModelView>(model)), planner_(plannerConfig(config), seed) {
  planner_.setModel(view_);
  const std::vector<rl_common::State> states = model.reachableStates();
  if (states.empty()) {
    throw std::invalid_argument("OptimalAgent::OptimalAgent(): the model has no states");
  }
  planner_.addStates(states);
  planner_.plan(states.front(), rl_common::PlanningBudget{});
}

int OptimalAgent::act(const rl_common::State& s) {
  planner_.plan(s, rl_common::PlanningBudget{});  // cheap once converged
  return planner_.bestAction(s);
}

}  // namespace rl_agent
