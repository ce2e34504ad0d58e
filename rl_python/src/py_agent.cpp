#include "rl_python/py_agent.h"

#include <stdexcept>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_common/registry.h"
#include "rl_common/true_model.h"

namespace rl_python {

PyAgent::PyAgent(const std::string& name, const OptionValues& options,
                 const rl_common::EnvironmentDescription& task,
                 const EnvironmentFactory& trueModelSource, const std::string& trueModelNames) {
  // The agent node's parser and steps (rl_agent/src/ros/agent_node_main.cpp).
  rl_common::OptionParser parser("make_agent", "make_agent(name, env, **options)");
  rl_agent::addAgentOptions(parser, &options_);
  parser.value("seed", &options_.seed, "seed of the agent's random source");
  parser.set("agent", name);
  applyOptionValues(parser, options);
  const rl_agent::AgentRegistry& registry = rl_agent::agentRegistry();
  options_.agent = registry.canonical(options_.agent);
  rl_agent::applyAgentDefaults(parser, &options_);
  rl_agent::checkAgentOptions(parser, options_);
  effective_ = parser.currentValues();
  const rl_common::TrueModel* trueModel = nullptr;
  if (registry.hasFact(options_.agent, rl_agent::kTrueModelPlannerFact)) {
    if (trueModelSource) modelEnv_ = trueModelSource();
    trueModel = dynamic_cast<const rl_common::TrueModel*>(modelEnv_.get());
    if (trueModel == nullptr) {
      throw rl_common::OptionError("agent " + options_.agent +
                                   " plans on the environment's true model: give make_agent an "
                                   "environment with one (" +
                                   trueModelNames + ")");
    }
  }
  agent_ = rl_agent::makeAgent(options_, task, trueModel);
}

int PyAgent::firstAction(const rl_common::State& s) {
  lastReward_ = 0.0f;
  return agent_->firstAction(s);
}

int PyAgent::nextAction(float reward, const rl_common::State& s) {
  lastReward_ = reward;
  return agent_->nextAction(reward, s);
}

void PyAgent::lastAction(float reward) {
  lastReward_ = reward;
  agent_->lastAction(reward);
}

std::optional<RewardParts> PyAgent::rewardBreakdown() const {
  // Only the model-based agents have intrinsic rewards (a DiscretizationAgent around a
  // model-free one is a RewardBreakdownSource of zeros).
  const auto* source = dynamic_cast<const rl_agent::RewardBreakdownSource*>(agent_.get());
  if (source == nullptr ||
      !rl_agent::agentRegistry().hasFact(options_.agent, rl_agent::kModelBasedFact)) {
    return std::nullopt;
  }
  const rl_agent::RewardBreakdown b = source->lastRewardBreakdown();
  RewardParts parts;
  parts.external = lastReward_;
  parts.variance = b.variance;
  parts.novelty = b.novelty;
  parts.other = b.other;
  parts.plannedValue = b.plannedValue;
  parts.valueSpread = b.valueSpread;
  return parts;
}

void PyAgent::setIntrinsicEnabled(bool enabled) {
  auto* modelBased = dynamic_cast<rl_agent::ModelBasedAgent*>(agent_.get());
  if (modelBased == nullptr) {
    throw std::logic_error(
        "PyAgent::setIntrinsicEnabled(): agent " + options_.agent + " is not model-based (" +
        rl_common::joinNames(rl_agent::agentRegistry().namesWith(rl_agent::kModelBasedFact)) + ")");
  }
  modelBased->setIntrinsicEnabled(enabled);
}

}  // namespace rl_python
