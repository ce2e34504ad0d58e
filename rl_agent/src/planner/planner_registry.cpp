#include "rl_agent/planner/planner_registry.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rl_agent/planner/policy_iteration.h"
#include "rl_agent/planner/prioritized_sweeping.h"
#include "rl_agent/planner/value_iteration.h"
#include "rl_common/random.h"

namespace rl_agent {

namespace {

using Model = std::unique_ptr<rl_common::MDPModel>;

std::unique_ptr<PlanningLoop> syncSearch(const PlannerSettings& s, Model model) {
  return std::make_unique<SyncPlanningLoop>(
      std::move(model), std::make_unique<UctPlanner>(s.search, s.seed), s.rollouts, s.lazyViews);
}

std::unique_ptr<PlanningLoop> realTimeSearch(const PlannerSettings& s, Model model) {
  if (s.rollouts > 0) return syncSearch(s, std::move(model));
  // Root-parallel search: tree 0 keeps the planner's seed, the others get streams of their own.
  // The trees share one memory budget (their tables and prediction caches split it), so
  // memory does not grow with the number of threads.
  const int threads = std::max(1, s.searchThreads);
  std::vector<std::unique_ptr<UctPlanner>> planners;
  for (int k = 0; k < threads; ++k) {
    UctPlanner::Config c = s.search;
    if (threads > 1) {
      const auto share = static_cast<std::size_t>(threads);
      c.maxStates = std::max<std::size_t>(1000, c.maxStates / share);
      c.maxCachedPredictions = std::max<std::size_t>(1000, c.maxCachedPredictions / share);
    }
    planners.push_back(std::make_unique<UctPlanner>(
        c, k == 0
               ? s.seed
               : rl_common::Random::deriveSeed(s.seed, "search", static_cast<std::uint64_t>(k))));
  }
  RealTimePlanner::Config rt;
  rt.seed = rl_common::Random::deriveSeed(s.seed, "search-ties");
  return std::make_unique<RealTimePlanningLoop>(std::move(model), std::move(planners), rt);
}

template <class Solver>
PlannerRegistry::Factory dynamicProgramming(int maxSteps) {
  return [maxSteps](const PlannerSettings& s, Model model) -> std::unique_ptr<PlanningLoop> {
    if (s.search.history > 0) {
      throw std::invalid_argument(
          "option --history needs a UCT planner (dynamic programming plans on states alone)");
    }
    StateSpacePlanner::Config c = s.dp;
    c.maxSteps = maxSteps;
    return std::make_unique<SyncPlanningLoop>(std::move(model), std::make_unique<Solver>(c, s.seed),
                                              s.rollouts, s.lazyViews);
  };
}

}  // namespace

const PlannerRegistry& plannerRegistry() {
  static const PlannerRegistry registry = [] {
    PlannerRegistry reg("planner");
    const std::vector<std::string> search{kSearchPlannerFact};
    const std::vector<std::string> realTime{kSearchPlannerFact, kRealTimePlannerFact};
    reg.add("uct", syncSearch, "UCT(lambda), synchronously each step", search);
    reg.add("delayed-uct", syncSearch, "UCT(lambda) with action histories (as uct)", search);
    reg.add("parallel-uct", realTimeSearch, "UCT(lambda) in the real-time architecture", realTime);
    reg.add("delayed-parallel-uct", realTimeSearch,
            "real-time UCT(lambda) with action histories (as parallel-uct)", realTime);
    // The original's MAX_STEPS of each solver.
    reg.add("vi", dynamicProgramming<ValueIteration>(100), "value iteration");
    reg.add("pi", dynamicProgramming<PolicyIteration>(10), "policy iteration");
    reg.add("sweeping", dynamicProgramming<PrioritizedSweeping>(10), "prioritized sweeping");
    reg.addAlias("valueiteration", "vi");
    reg.addAlias("policyiteration", "pi");
    reg.addAlias("prioritizedsweeping", "sweeping");
    reg.addAlias("paralleluct", "parallel-uct");
    reg.addAlias("realtimeuct", "parallel-uct");
    reg.addAlias("realtime-uct", "parallel-uct");
    reg.addAlias("delayeduct", "delayed-uct");
    reg.addAlias("delayedparalleluct", "delayed-parallel-uct");
    return reg;
  }();
  return registry;
}

std::unique_ptr<PlanningLoop> makePlanningLoop(const std::string& planner,
                                               const PlannerSettings& settings,
                                               std::unique_ptr<rl_common::MDPModel> model) {
  return plannerRegistry().create(planner, settings, std::move(model));
}

}  // namespace rl_agent
