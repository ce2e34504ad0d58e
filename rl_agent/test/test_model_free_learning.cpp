// Q-learning, Sarsa(λ) and Dyna-Q learn the two-room grid (seeded, shortest path 10 steps).
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/dyna.h"
#include "small_mdps.h"

namespace {

rl_agent::AgentOptions options(const std::string& agent) {
  rl_agent::AgentOptions o;
  o.agent = agent;
  o.seed = 5;
  o.gamma = 0.95f;
  o.alpha = 0.3f;
  o.epsilon = 0.05f;
  o.lambda = 0.5f;
  o.k = 20;
  return o;
}

/// Mean steps of the last 20 of `episodes` episodes.
double learn(const std::string& agentName, int episodes) {
  auto agent = rl_agent::makeAgent(options(agentName), test_mdps::TwoRoomGrid::describe());
  test_mdps::TwoRoomGrid env;
  std::vector<int> steps;
  for (int e = 0; e < episodes; ++e) steps.push_back(test_mdps::runEpisode(*agent, env, 500));
  return std::accumulate(steps.end() - 20, steps.end(), 0.0) / 20.0;
}

}  // namespace

// A random walk needs hundreds of steps; the optimum is 10 (plus epsilon-greedy detours).
TEST(ModelFreeLearning, QLearnerLearnsTwoRoomGrid) { EXPECT_LT(learn("qlearner", 300), 14.0); }

TEST(ModelFreeLearning, SarsaLearnsTwoRoomGrid) { EXPECT_LT(learn("sarsa", 300), 14.0); }

TEST(ModelFreeLearning, DynaLearnsTwoRoomGrid) { EXPECT_LT(learn("dyna", 60), 14.0); }

TEST(ModelFreeLearning, DynaLearnsFasterThanQLearning) {
  // After 30 episodes, 20 replays per step have propagated far more value.
  EXPECT_LT(learn("dyna", 30), learn("qlearner", 30));
}

TEST(Dyna, ReplaysStoredExperience) {
  rl_agent::Dyna::Config c;
  c.numActions = 1;
  c.gamma = 0.9f;
  c.alpha = 0.5f;
  c.epsilon = 0.0f;
  c.k = 10;
  rl_agent::Dyna agent(c, 1);
  agent.firstAction({0});
  agent.lastAction(1.0f);  // Q = 0.5 from the real update
  EXPECT_FLOAT_EQ(agent.q({0}, 0), 0.5f);
  agent.firstAction({1});  // 10 replays of the stored terminal transition: Q = 1 − 0.5^11
  EXPECT_NEAR(agent.q({0}, 0), 1.0 - std::pow(0.5, 11), 1e-6);
  EXPECT_EQ(agent.numStored(), 1u);
}
