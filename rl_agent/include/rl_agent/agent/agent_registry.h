/**
 * The agent registry: every agent of the suite under the original's --agent names, plus
 * `optimal` (value iteration on the environment's true model; built only through the
 * makeAgent overload that receives that model: the experiment runner passes its environment,
 * the agent node its own copy of the environment named by --env). With --nstates binning a
 * feature, the model-free agents and savedpolicy are wrapped in a DiscretizationAgent, as in the
 * original.
 */
#pragma once

#include <memory>

#include "rl_agent/agent/agent_options.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/registry.h"
#include "rl_common/true_model.h"

namespace rl_agent {

/// Facts of the registry's entries: tabular learners without a model (their options --alpha,
/// --initialvalue), model-based agents (the model, planner and exploration options), and the
/// agents that see --nstates-binned states through a DiscretizationAgent; and the agents that
/// plan on the environment's true model (optimal: only a program that can build the
/// environment offers them, as the runner and rl_experiment's optimal_agent node do).
inline constexpr const char* kModelFreeFact = "model-free";
inline constexpr const char* kTrueModelPlannerFact = "plans-on-true-model";
inline constexpr const char* kModelBasedFact = "model-based";
inline constexpr const char* kBinnedStatesFact = "binned-states";

/// Factories take the options (including the seed) and the task description.
using AgentRegistry = rl_common::Registry<rl_common::Agent, const AgentOptions&,
                                          const rl_common::EnvironmentDescription&>;

const AgentRegistry& agentRegistry();

/// Builds `options.agent` for the task `description`. Throws std::invalid_argument listing the
/// valid names if the name is unknown.
std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description);

/// Same, with access to the environment's exact dynamics for the `optimal` agent (every other
/// agent ignores `trueModel`). The runner passes
/// `dynamic_cast<const rl_common::TrueModel*>(env.get())`; the environment must outlive the
/// agent. Throws std::invalid_argument if `optimal` is asked for and `trueModel` is null.
std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description,
                                            const rl_common::TrueModel* trueModel);

}  // namespace rl_agent
