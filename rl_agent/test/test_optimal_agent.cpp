// The optimal agent: value iteration on a true model, checked against hand-computed values.
#include "rl_agent/agent/optimal_agent.h"

#include <gtest/gtest.h>

#include <cmath>

#include "rl_agent/agent/agent_registry.h"
#include "small_mdps.h"

using rl_agent::OptimalAgent;
using rl_common::State;

namespace {
OptimalAgent::Config config(double gamma) {
  OptimalAgent::Config c;
  c.numActions = 4;
  c.gamma = gamma;
  return c;
}
}  // namespace

TEST(OptimalAgent, ValuesAndReturnOnTheDeterministicGrid) {
  test_mdps::TwoRoomGrid grid;
  OptimalAgent agent(config(0.9), grid, 1);
  EXPECT_EQ(agent.numStates(), 31u);
  // 10 steps of reward −1 to the goal: V = −(1 − 0.9^10) / (1 − 0.9).
  EXPECT_NEAR(agent.value({0, 0}), -(1.0 - std::pow(0.9, 10)) / 0.1, 1e-5);
  EXPECT_NEAR(agent.value({5, 4}), -1.0, 1e-6);  // one step from the goal
  // Its return: exactly the shortest path, −10, every episode.
  for (int e = 0; e < 5; ++e) EXPECT_EQ(test_mdps::runEpisode(agent, grid, 100), 10);
}

TEST(OptimalAgent, StochasticValuesMatchTheBellmanEquation) {
  // With slips, V(5,4) under "go east": V = −1 + γ·(0.1·V(5,4) + 0.1·V(5,3))... check the
  // Bellman equation holds at every state instead of a closed form.
  test_mdps::TwoRoomGrid grid(0.2);
  const double gamma = 0.95;
  OptimalAgent agent(config(gamma), grid, 1);
  for (const State& s : grid.reachableStates()) {
    if (test_mdps::TwoRoomGrid::goal(s)) continue;
    double best = -1e9;
    for (int a = 0; a < 4; ++a) {
      double q = 0.0;
      for (const auto& o : grid.transitions(s, a)) {
        q += o.probability * (o.reward + (o.terminal ? 0.0 : gamma * agent.value(o.next)));
      }
      best = std::max(best, q);
    }
    EXPECT_NEAR(agent.value(s), best, 1e-4);
  }
  // Slips only slow it down: the mean episode length is a little above 10.
  double steps = 0.0;
  for (int e = 0; e < 200; ++e) steps += test_mdps::runEpisode(agent, grid, 1000);
  EXPECT_GT(steps / 200, 10.0);
  EXPECT_LT(steps / 200, 16.0);
}

TEST(OptimalAgent, BuiltThroughTheRegistryOnlyWithATrueModel) {
  rl_agent::AgentOptions o;
  o.agent = "optimal";
  o.gamma = 0.9f;
  const auto d = test_mdps::TwoRoomGrid::describe();
  EXPECT_THROW(rl_agent::makeAgent(o, d), std::invalid_argument);
  EXPECT_THROW(rl_agent::makeAgent(o, d, nullptr), std::invalid_argument);
  test_mdps::TwoRoomGrid grid;
  auto agent = rl_agent::makeAgent(o, d, &grid);
  EXPECT_EQ(test_mdps::runEpisode(*agent, grid, 100), 10);
  // Other agents ignore the true model.
  o.agent = "qlearner";
  EXPECT_NE(rl_agent::makeAgent(o, d, &grid), nullptr);
}

TEST(OptimalAgent, TrueModelMismatchNamesEveryDifference) {
  const rl_common::EnvironmentDescription model = test_mdps::TwoRoomGrid::describe();
  EXPECT_EQ(rl_agent::trueModelMismatch(model, model), "");

  rl_common::EnvironmentDescription other = model;
  other.title = "Environment: something else\n";  // titles do not matter
  EXPECT_EQ(rl_agent::trueModelMismatch(model, other), "");

  other.numActions = model.numActions + 1;
  other.maxFeatures[1] += 2.0f;
  other.stochastic = !model.stochastic;
  const std::string m = rl_agent::trueModelMismatch(model, other);
  EXPECT_NE(m.find(std::to_string(other.numActions) + " actions, the model has " +
                   std::to_string(model.numActions)),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("feature 1 range"), std::string::npos) << m;
  EXPECT_EQ(m.find("feature 0"), std::string::npos) << m;
  EXPECT_NE(m.find("--stochastic / --deterministic"), std::string::npos) << m;

  rl_common::EnvironmentDescription fewer = model;
  fewer.minFeatures.pop_back();
  fewer.maxFeatures.pop_back();
  EXPECT_NE(rl_agent::trueModelMismatch(model, fewer).find("features, the model has"),
            std::string::npos);

  rl_common::EnvironmentDescription rewards = model;
  rewards.maxReward += 1.0f;
  rewards.episodic = !model.episodic;
  const std::string r = rl_agent::trueModelMismatch(model, rewards);
  EXPECT_NE(r.find("reward range"), std::string::npos) << r;
  EXPECT_NE(r.find("episodic"), std::string::npos) << r;
}
