/**
 * The Q-values a model-based agent's planners hold, as the original's policy-file table
 * (PolicyFile), for `savedpolicy` to act greedily on.
 *
 *   dynamic programming (vi, pi, sweeping): every state the planner expanded;
 *   search (UCT): every state of every search tree (states binned with --nstates); with an
 *     action history a state has one record per history, and the table (keyed by state
 *     alone) keeps the values of its most visited record over all trees.
 */
#pragma once

#include <cstddef>

#include "rl_agent/agent/policy_file.h"
#include "rl_agent/planner/planning_loop.h"

namespace rl_agent {

/// The table of `loop`'s planner for states of `numFeatures` features and `numActions` actions.
PolicyFile::Table policyTable(PlanningLoop& loop, std::size_t numFeatures, int numActions);

}  // namespace rl_agent
