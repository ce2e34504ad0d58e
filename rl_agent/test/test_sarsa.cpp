#include "rl_agent/agent/sarsa.h"

#include <gtest/gtest.h>

using rl_agent::Sarsa;
using rl_common::State;

namespace {
Sarsa::Config config(int actions, float lambda) {
  Sarsa::Config c;
  c.numActions = actions;
  c.gamma = 0.9f;
  c.alpha = 0.5f;
  c.epsilon = 0.0f;
  c.lambda = lambda;
  return c;
}
}  // namespace

TEST(Sarsa, HandComputedTraceUpdates) {
  // One action, chain s0 -> s1 -> s2 (terminal). γλ = 0.9 * 0.5 = 0.45.
  Sarsa agent(config(1, 0.5f), 1);
  const State s0{0}, s1{1};
  agent.firstAction(s0);
  // δ = 1 + 0.9 * Q(s1) − Q(s0) = 1: Q(s0) = 0.5 * 1 * 1 = 0.5; e(s0) = 0.45.
  agent.nextAction(1.0f, s1);
  EXPECT_FLOAT_EQ(agent.q(s0, 0), 0.5f);
  // Terminal with reward 2: δ = 2 − Q(s1) = 2; Q(s1) = 0.5 * 2 * 1 = 1;
  // Q(s0) = 0.5 + 0.5 * 2 * 0.45 = 0.95 (the standard γλ trace).
  agent.lastAction(2.0f);
  EXPECT_FLOAT_EQ(agent.q(s1, 0), 1.0f);
  EXPECT_FLOAT_EQ(agent.q(s0, 0), 0.95f);
  EXPECT_EQ(agent.numTraces(), 0u);  // cleared at the end of the episode
}

TEST(Sarsa, LambdaZeroIsOneStepSarsa) {
  Sarsa agent(config(1, 0.0f), 1);
  const State s0{0}, s1{1};
  agent.firstAction(s0);
  agent.nextAction(1.0f, s1);
  agent.lastAction(2.0f);
  EXPECT_FLOAT_EQ(agent.q(s0, 0), 0.5f);  // no trace reaches s0
  EXPECT_FLOAT_EQ(agent.q(s1, 0), 1.0f);
}

TEST(Sarsa, ReplacingTraceResetsToOne) {
  Sarsa agent(config(1, 1.0f), 1);
  const State s0{0};
  agent.firstAction(s0);
  agent.nextAction(0.0f, s0);  // revisit s0: its trace is 1, not 1 + 0.9
  agent.nextAction(0.0f, s0);
  EXPECT_EQ(agent.numTraces(), 1u);
}

TEST(Sarsa, RejectsBadConfig) {
  EXPECT_THROW(Sarsa(config(0, 0.5f), 1), std::invalid_argument);
  EXPECT_THROW(Sarsa(config(2, 1.5f), 1), std::invalid_argument);
  Sarsa agent(config(2, 0.5f), 1);
  EXPECT_THROW(agent.nextAction(0.0f, State{0}), std::logic_error);
}
