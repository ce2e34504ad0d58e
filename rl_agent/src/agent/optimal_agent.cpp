#include "rl_agent/agent/optimal_agent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
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

std::string trueModelMismatch(const rl_common::EnvironmentDescription& model,
                              const rl_common::EnvironmentDescription& received) {
  std::ostringstream out;
  const auto clause = [&out]() -> std::ostringstream& {
    if (out.tellp() > 0) out << "; ";
    return out;
  };
  // Ranges travel as float32 on both sides: equal up to rounding.
  const auto same = [](float a, float b) {
    return std::fabs(a - b) <= 1e-6f * std::max(1.0f, std::max(std::fabs(a), std::fabs(b)));
  };
  if (received.numActions != model.numActions) {
    clause() << received.numActions << " actions, the model has " << model.numActions;
  }
  if (received.numFeatures() != model.numFeatures() ||
      received.maxFeatures.size() != model.maxFeatures.size()) {
    clause() << received.numFeatures() << " features, the model has " << model.numFeatures();
  } else {
    for (std::size_t j = 0; j < model.numFeatures(); ++j) {
      if (!same(received.minFeatures[j], model.minFeatures[j]) ||
          !same(received.maxFeatures[j], model.maxFeatures[j])) {
        clause() << "feature " << j << " range [" << received.minFeatures[j] << ", "
                 << received.maxFeatures[j] << "], the model's [" << model.minFeatures[j] << ", "
                 << model.maxFeatures[j] << "]";
      }
    }
  }
  if (!same(received.minReward, model.minReward) || !same(received.maxReward, model.maxReward)) {
    clause() << "reward range [" << received.minReward << ", " << received.maxReward
             << "], the model's [" << model.minReward << ", " << model.maxReward << "]";
  }
  if (received.episodic != model.episodic) {
    clause() << (received.episodic ? "episodic" : "not episodic") << ", the model "
             << (model.episodic ? "is" : "is not");
  }
  if (received.stochastic != model.stochastic) {
    clause() << (received.stochastic ? "stochastic" : "deterministic") << ", the model "
             << (model.stochastic ? "stochastic" : "deterministic")
             << " (--stochastic / --deterministic)";
  }
  return out.str();
}

}  // namespace rl_agent
