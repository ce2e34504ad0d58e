#include "rl_agent/agent/q_learner.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "rl_agent/agent/agent_registry.h"

using rl_agent::QLearner;
using rl_common::State;

namespace {

QLearner::Config config(int actions, float epsilon) {
  QLearner::Config c;
  c.numActions = actions;
  c.gamma = 0.9f;
  c.alpha = 0.5f;
  c.epsilon = epsilon;
  return c;
}

}  // namespace

TEST(QLearner, HandComputedUpdates) {
  QLearner agent(config(2, 0.0f), 1);
  const State s0{0}, s1{1};
  const int a0 = agent.firstAction(s0);
  agent.nextAction(1.0f, s1);  // Q(s0,a0) = 0 + 0.5 * (1 + 0.9 * 0 - 0) = 0.5
  EXPECT_FLOAT_EQ(agent.q(s0, a0), 0.5f);
  EXPECT_FLOAT_EQ(agent.q(s0, 1 - a0), 0.0f);
}

TEST(QLearner, TerminalStepDoesNotBootstrap) {
  QLearner agent(config(1, 0.0f), 1);
  const State s0{0}, s1{1};
  agent.seedExperiences({{s1, 0, 4.0f, s0, false}});  // Q(s1) = 2
  agent.firstAction(s0);
  agent.lastAction(2.0f);  // terminal: Q(s0) = 0.5 * 2 = 1, no 0.9 * Q(next)
  EXPECT_FLOAT_EQ(agent.q(s0, 0), 1.0f);
  EXPECT_FLOAT_EQ(agent.q(s1, 0), 2.0f);
  agent.seedExperiences({{s0, 0, 0.0f, s1, false}});  // 1 + 0.5 * (0 + 0.9 * 2 - 1) = 1.4
  EXPECT_FLOAT_EQ(agent.q(s0, 0), 1.4f);
}

TEST(QLearner, LearnsToWalkRightInAChain) {
  // Chain of 6 cells; action 1 moves right, 0 left; reaching cell 5 pays +1 and ends.
  QLearner agent(config(2, 0.1f), 7);
  for (int episode = 0; episode < 300; ++episode) {
    int pos = 0;
    int a = agent.firstAction({float(pos)});
    for (int step = 0; step < 200; ++step) {
      pos = std::max(0, pos + (a == 1 ? 1 : -1));
      if (pos == 5) {
        agent.lastAction(1.0f);
        break;
      }
      a = agent.nextAction(0.0f, {float(pos)});
    }
  }
  for (int pos = 0; pos < 5; ++pos) {
    EXPECT_GT(agent.q({float(pos)}, 1), agent.q({float(pos)}, 0)) << "cell " << pos;
    EXPECT_EQ(agent.greedyAction({float(pos)}), 1);
  }
}

TEST(QLearner, SameSeedSameActions) {
  QLearner a(config(4, 0.5f), 3), b(config(4, 0.5f), 3);
  int x = a.firstAction({0}), y = b.firstAction({0});
  for (int i = 0; i < 200; ++i) {
    ASSERT_EQ(x, y);
    x = a.nextAction(float(i % 3), {float(i % 7)});
    y = b.nextAction(float(i % 3), {float(i % 7)});
  }
}

TEST(QLearner, RejectsBadConfigurationAndProtocolMisuse) {
  EXPECT_THROW(QLearner(config(0, 0.1f), 1), std::invalid_argument);
  EXPECT_THROW(QLearner(config(2, 1.5f), 1), std::invalid_argument);
  QLearner agent(config(2, 0.1f), 1);
  EXPECT_THROW(agent.nextAction(0.0f, {0}), std::logic_error);
  EXPECT_THROW(agent.seedExperiences({{{0}, 5, 0.0f, {1}, false}}), std::invalid_argument);
}

TEST(AgentRegistry, BuildsQLearnerAndRejectsUnknownNames) {
  rl_agent::AgentOptions o;
  o.agent = "qlearner";
  rl_common::EnvironmentDescription d;
  d.numActions = 3;
  auto agent = rl_agent::makeAgent(o, d);
  const int a = agent->firstAction({0.0f});
  EXPECT_GE(a, 0);
  EXPECT_LT(a, 3);
  o.agent = "nosuch";
  try {
    rl_agent::makeAgent(o, d);
    FAIL();
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("unknown agent 'nosuch'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("qlearner"), std::string::npos) << msg;
    EXPECT_NE(msg.find("texplore"), std::string::npos) << msg;
  }
}
