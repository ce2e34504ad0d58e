/**
 * The agent registry: every agent of the suite under the original's --agent names.
 */
#pragma once

#include <memory>

#include "rl_agent/agent/agent_options.h"
#include "rl_common/agent.h"
#include "rl_common/environment.h"
#include "rl_common/registry.h"

namespace rl_agent {

/// Factories take the options (including the seed) and the task description.
using AgentRegistry = rl_common::Registry<rl_common::Agent, const AgentOptions&,
                                          const rl_common::EnvironmentDescription&>;

const AgentRegistry& agentRegistry();

/// Builds `options.agent` for the task `description`. Throws std::invalid_argument listing the
/// valid names if the name is unknown.
std::unique_ptr<rl_common::Agent> makeAgent(const AgentOptions& options,
                                            const rl_common::EnvironmentDescription& description);

}  // namespace rl_agent
