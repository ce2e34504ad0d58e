#include "rl_experiment/runner/agent_probe.h"

#include <stdexcept>
#include <string>

#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/journal/journaling_agent.h"

namespace rl_experiment {

namespace {

// The agent itself, under a journal (--journal) if there is one.
const rl_common::Agent& core(const rl_common::Agent& agent) {
  if (const auto* j = dynamic_cast<const rl_agent::JournalingAgent*>(&agent)) return j->inner();
  return agent;
}
rl_common::Agent& core(rl_common::Agent& agent) {
  if (auto* j = dynamic_cast<rl_agent::JournalingAgent*>(&agent)) return j->inner();
  return agent;
}

}  // namespace

std::optional<rl_agent::RewardBreakdown> rewardBreakdownOf(const rl_common::Agent& agent) {
  if (const auto* source = dynamic_cast<const rl_agent::RewardBreakdownSource*>(&core(agent))) {
    return source->lastRewardBreakdown();
  }
  return std::nullopt;
}

bool setIntrinsicEnabled(rl_common::Agent& agent, bool enabled) {
  if (auto* mb = dynamic_cast<rl_agent::ModelBasedAgent*>(&core(agent))) {
    mb->setIntrinsicEnabled(enabled);
    return true;
  }
  return false;
}

bool recordExperiences(rl_common::Agent& agent) {
  if (auto* mb = dynamic_cast<rl_agent::ModelBasedAgent*>(&core(agent))) {
    mb->recordExperiences(true);
    return true;
  }
  return false;
}

long giveTaskRewards(rl_common::Agent& agent, const std::vector<float>& stepRewards) {
  auto* mb = dynamic_cast<rl_agent::ModelBasedAgent*>(&core(agent));
  if (mb == nullptr) return -1;
  const std::size_t n = mb->recordedSteps();
  if (n > stepRewards.size()) {
    throw std::logic_error("giveTaskRewards(): the agent learned " + std::to_string(n) +
                           " steps, more than the " + std::to_string(stepRewards.size()) +
                           " steps taken");
  }
  mb->relabelRewards(std::vector<float>(stepRewards.begin(), stepRewards.begin() + long(n)));
  return static_cast<long>(n);
}

std::shared_ptr<const rl_common::ModelView> learnedModelOf(const rl_common::Agent& agent) {
  // Every model kind (trees, tabular, m5tree, R-MAX's): its predictions without intrinsic
  // bonuses or optimism in the transitions.
  if (const auto* mb = dynamic_cast<const rl_agent::ModelBasedAgent*>(&core(agent))) {
    return mb->learnedModelView();
  }
  return nullptr;
}

}  // namespace rl_experiment
