/**
 * Agent probes: what the experiment runner may ask of an agent beyond rl_common::Agent, found
 * at run time so that every agent of the registry runs, and agents that offer more are logged
 * in more detail: the intrinsic reward parts of the last action (rl_agent::RewardBreakdownSource),
 * switching intrinsic rewards off for the task phase, and the learned model for the accuracy
 * evaluation (rl_agent::ModelBasedAgent).
 */
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "rl_agent/agent/reward_breakdown_source.h"
#include "rl_common/agent.h"
#include "rl_common/mdp_model.h"

namespace rl_experiment {

/// The intrinsic parts of the agent's last action, if the agent reports them.
std::optional<rl_agent::RewardBreakdown> rewardBreakdownOf(const rl_common::Agent& agent);

/// Switches the agent's intrinsic rewards on or off. Returns false if the agent has none.
bool setIntrinsicEnabled(rl_common::Agent& agent, bool enabled);

/// Makes a model-based agent keep its experiences (for giveTaskRewards). Returns false for
/// other agents.
bool recordExperiences(rl_common::Agent& agent);

/// Gives a model-based agent the task's reward of each step it has learned from so far: the
/// first agent.recordedSteps() entries of `stepRewards` (rl_agent::ModelBasedAgent::
/// relabelRewards). Returns the number of rewards used, or -1 if the agent learns no model.
long giveTaskRewards(rl_common::Agent& agent, const std::vector<float>& stepRewards);

/// The agent's learned model as it is now (predicted next-state distributions), or null if the
/// agent learns no model.
std::shared_ptr<const rl_common::ModelView> learnedModelOf(const rl_common::Agent& agent);

}  // namespace rl_experiment
