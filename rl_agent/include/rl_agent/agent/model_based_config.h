/**
 * ModelBasedConfig: the typed configuration of a ModelBasedAgent, one field group per part
 * (model, planning loop, explorer and action choice, one-way-step deferral, task phase), each
 * in the type its component takes. modelBasedConfig() builds it from the command-line
 * options, which hold the defaults (AgentOptions, once each).
 */
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "rl_agent/agent/agent_options.h"
#include "rl_agent/model/model_registry.h"
#include "rl_agent/planner/planner_registry.h"
#include "rl_agent/planner/task_phase_planner.h"
#include "rl_agent/planner/uct_planner.h"
#include "rl_agent/reward/explorer_registry.h"
#include "rl_common/environment.h"

namespace rl_agent {

struct ModelBasedConfig {
  struct Ucb {
    UctPlanner::UcbBound bound = UctPlanner::UcbBound::Range;
    double c = 1.0;
  };

  std::string model;     ///< model registry name
  ModelSettings models;  ///< its settings (the explorer and seed are set by the agent)
  std::string planner;   ///< planner registry name
  PlannerSettings planning;
  double actRate = 0.0;  ///< actions per second: when an action is due
  std::string explore;   ///< explorer registry name
  ExplorerSettings explorer;
  double epsilon = 0.0;           ///< ε of ε-greedy action choice
  std::vector<int> statesPerDim;  ///< --nstates binning of the model's inputs; empty: none
  int history = 0;                ///< actions of history in the model's input
  long defer = 0;                 ///< --defer; 0: never
  long deferRegions = 0;          ///< --deferregions
  Ucb exploreUcb;                 ///< UCB bound while exploring (--ucb, --ucbc)
  /// UCB bound of the task phase (--taskucb, --taskucbc); unset: the exploring one.
  bool taskUcbGiven = false;
  Ucb taskUcb;
  bool taskPlanner = false;  ///< --taskplanner vi: the task phase plans by value iteration
  TaskPhasePlanner::Config taskPhase;
  /// --taskcombo: the forests' combination for the task phase's planning; unset: the model's.
  std::optional<Combination> taskCombination;
  std::vector<int> taskKey;  ///< --taskkey (checked against the task's features)
  std::uint64_t seed = 0;    ///< every part's seed derives from it
};

/// The configuration `options` (after applyAgentDefaults) give for `task`.
ModelBasedConfig modelBasedConfig(const AgentOptions& options,
                                  const rl_common::EnvironmentDescription& task);

}  // namespace rl_agent
