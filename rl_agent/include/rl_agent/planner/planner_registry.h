/**
 * The planner registry: each --planner value names how a model-based agent plans on its
 * learned model, with the facts its option checks need; an entry builds the agent's
 * PlanningLoop around the model:
 *
 *   uct, delayed-uct                  UCT(λ) planned synchronously each step (search)
 *   parallel-uct, delayed-parallel-uct
 *                                     UCT(λ) in the RTMBA real-time architecture (search,
 *                                     real time); synchronous with --rollouts
 *   vi, pi, sweeping                  value iteration, policy iteration, prioritized sweeping,
 *                                     solved after every model update (dynamic programming)
 *
 * Our UctPlanner keys its values by state and action history, which is what the original's
 * delayed (PO_) variants added, so the delayed names build the same planners.
 */
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "rl_agent/planner/planning_loop.h"
#include "rl_agent/planner/state_space_planner.h"
#include "rl_agent/planner/uct_planner.h"
#include "rl_common/mdp_model.h"
#include "rl_common/registry.h"

namespace rl_agent {

struct PlannerSettings {
  UctPlanner::Config search;     ///< search planners' configuration
  StateSpacePlanner::Config dp;  ///< dynamic-programming planners' (maxSteps set by the entry)
  long rollouts = 0;             ///< per step; 0: until the action is due (or converged)
  int searchThreads = 1;         ///< real time: root-parallel search trees
  /// A model update reaches the planner at the agent's next view filter (StepDeferral).
  bool lazyViews = false;
  std::uint64_t seed = 0;  ///< the planner's seed; search threads after the first derive theirs
};

/// A UCT search planner (takes --history, --rollouts, --lambda and the UCB options).
inline constexpr const char* kSearchPlannerFact = "search";
/// Plans in the real-time architecture unless given --rollouts (takes --searchthreads).
inline constexpr const char* kRealTimePlannerFact = "real-time";

using PlannerRegistry =
    rl_common::Registry<PlanningLoop, const PlannerSettings&, std::unique_ptr<rl_common::MDPModel>>;

const PlannerRegistry& plannerRegistry();

/// Builds `planner`'s loop around `model`. Throws std::invalid_argument for an unknown name.
std::unique_ptr<PlanningLoop> makePlanningLoop(const std::string& planner,
                                               const PlannerSettings& settings,
                                               std::unique_ptr<rl_common::MDPModel> model);

}  // namespace rl_agent
