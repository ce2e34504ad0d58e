#include "rl_agent/agent/model_based_config.h"

#include <algorithm>

#include "rl_common/random.h"

namespace rl_agent {

namespace {

ModelBasedConfig::Ucb ucbOf(const std::string& name, float c) {
  return {name == "normalized" ? UctPlanner::UcbBound::Normalized : UctPlanner::UcbBound::Range,
          static_cast<double>(c)};
}

}  // namespace

ModelBasedConfig modelBasedConfig(const AgentOptions& o,
                                  const rl_common::EnvironmentDescription& t) {
  ModelBasedConfig c;
  c.seed = o.seed;
  const bool binned = binsStates(o);

  c.explore = o.explore;
  ExplorerSettings& e = c.explorer;
  e.v = o.v;
  e.n = o.n;
  e.stateNovelty = o.novelty == "state";
  e.m = o.m;
  e.tau = o.tau;
  e.featMin = t.minFeatures;
  e.featMax = t.maxFeatures;
  e.seed = rl_common::Random::deriveSeed(o.seed, "regions");
  const float rmax = t.maxReward > 0.0f ? t.maxReward : 1.0f;
  e.rmax = rmax / (1.0f - std::min(o.gamma, 0.999f));  // the original's qmax
  c.epsilon = o.epsilon;

  c.model = o.model;
  ModelSettings& m = c.models;
  m.numActions = t.numActions;
  m.featMin = t.minFeatures;
  m.featMax = t.maxFeatures;
  m.episodic = t.episodic;
  m.rewardRange = t.rewardRange();
  m.extraInputs = o.history * t.numActions;
  m.relativeTransitions = o.reltrans;
  m.numTrees = o.nmodels;
  m.combination = o.combo;
  m.m = o.m;
  m.rmax = e.rmax;
  m.explore = o.explore;
  m.seed = rl_common::Random::deriveSeed(o.seed, "model");
  if (binned && modelRegistry().hasFact(o.model, kBinnedInputsFact)) c.statesPerDim = o.nstates;
  c.history = o.history;

  c.planner = o.planner;
  PlannerSettings& p = c.planning;
  p.seed = rl_common::Random::deriveSeed(o.seed, "planner");
  p.rollouts = o.rollouts;
  p.searchThreads = plansInRealTime(o) ? searchThreads(o) : 1;
  UctPlanner::Config& s = p.search;
  s.numActions = t.numActions;
  s.gamma = o.gamma;
  s.lambda = o.lambda;
  s.rewardRange = t.rewardRange();
  s.featMin = t.minFeatures;
  s.featMax = t.maxFeatures;
  if (binned) s.statesPerDim = o.nstates;
  s.history = o.history;
  s.trackActual = true;
  s.countPathVisits = o.pathvisits;
  s.bonusOncePerPath = o.bonusonce;
  s.maxDepth = o.depth;
  s.minOutcomeProbability = o.minprob;
  c.exploreUcb = ucbOf(o.ucb, o.ucbc);
  s.ucbBound = c.exploreUcb.bound;
  s.ucbC = c.exploreUcb.c;
  // Every dynamic-programming planner: actions, discount, the feature ranges (successors
  // outside them are not real: the original's check) and the --nstates grid.
  StateSpacePlanner::Config& dp = p.dp;
  dp.numActions = t.numActions;
  dp.gamma = std::min(static_cast<double>(o.gamma), 0.999999);
  dp.featMin = t.minFeatures;
  dp.featMax = t.maxFeatures;
  if (binned) dp.statesPerDim = o.nstates;  // the planner's grid, as the original's
  c.actRate = o.actrate;

  c.defer = o.defer;
  c.deferRegions = o.deferregions;
  c.taskUcbGiven = o.taskucb != "same";
  c.taskUcb = ucbOf(o.taskucb, o.taskucbc);

  c.taskPlanner = o.taskplanner == "vi";
  c.taskKey = o.taskkey;
  if (o.taskcombo != "same") c.taskCombination = combinationFromName(o.taskcombo);
  TaskPhasePlanner::Config& task = c.taskPhase;
  task.table = dp;
  task.table.maxSteps = o.taskdepth;
  task.table.maxStates = 20000;  // bounds a step's model queries (6 per state)
  // 0.01 plans better than the default 0.1 but takes 20 times longer (0.3 s against 15 ms a
  // step on LightWorld); the most likely outcome alone (0.5) strands the agent.
  task.table.minTransitionProbability = o.taskminprob;
  task.table.keyFeatures = o.taskkey;
  task.table.keyMarginal = o.taskoutcomes == "key";
  task.sweeps = o.tasksweeps;
  task.recent = o.taskrecent;
  task.seed = o.seed;
  return c;
}

}  // namespace rl_agent
