/**
 * The whole program of an agent node: options from the command line and ~private parameters
 * (the command line wins), --help without a master, the journal settings, Ctrl-C that ends a
 * long planning step, then an AgentNode until shutdown. rl_agent's `agent` node runs it
 * without a TrueModelSource; rl_experiment's optimal_agent node with the suite's environments.
 */
#pragma once

#include <string>

#include "rl_agent/agent/true_model_source.h"

namespace rl_agent {

/// Runs the node named `program` in messages, whose --agent is `defaultAgent` unless given;
/// `source` (may be null) builds the true model of the agents that plan on one. Returns
/// main()'s exit code: 0 after shutdown or --help, 2 for a bad option, 1 if the node failed.
/// Call ros::init (with ros::init_options::NoSigintHandler) first.
int runAgentNodeMain(int argc, char** argv, TrueModelSource* source, const std::string& program,
                     const std::string& defaultAgent);

}  // namespace rl_agent
