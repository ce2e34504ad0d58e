// R-MAX (tabular model, optimism for state-actions seen fewer than m times, value iteration)
// learns the two-room grid; the tabular model's counts.
#include <gtest/gtest.h>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "rl_agent/model/tabular_model.h"
#include "small_mdps.h"

using rl_agent::TabularModel;
using rl_common::State;

TEST(TabularModel, MaximumLikelihoodCounts) {
  TabularModel::Config c;
  c.numActions = 2;
  c.numFeatures = 1;
  c.m = 2;
  TabularModel model(c);
  auto v = model.tabularView();
  auto info = v->query({0}, 0);  // unseen: self-transition, −0.001, unknown
  EXPECT_FALSE(info.known);
  ASSERT_EQ(info.transitions.size(), 1u);
  EXPECT_EQ(info.transitions[0].first, State{0});
  EXPECT_FLOAT_EQ(info.reward, -0.001f);
  model.update({{{0}, 0, 1.0f, {1}, false},
                {{0}, 0, 3.0f, {2}, false},
                {{0}, 0, 2.0f, {1}, false},
                {{0}, 0, 2.0f, {0}, true}});
  info = model.tabularView()->query({0}, 0);
  EXPECT_TRUE(info.known);
  EXPECT_FLOAT_EQ(info.reward, 2.0f);
  EXPECT_FLOAT_EQ(info.termProb, 0.25f);
  ASSERT_EQ(info.transitions.size(), 2u);
  EXPECT_DOUBLE_EQ(info.transitions[0].second, 2.0 / 3.0);  // {1}: 2 of 3 non-terminal
  EXPECT_THROW(model.update({{{0}, 5, 0.0f, {0}, false}}), std::invalid_argument);
  EXPECT_EQ(v->visits({0}, 0), 0);  // old views do not change
}

TEST(TabularModel, RmaxOptimismUntilKnownThenFrozen) {
  TabularModel::Config c;
  c.numActions = 1;
  c.numFeatures = 1;
  c.m = 2;
  c.optimistic = true;
  c.rmax = 50.0f;
  TabularModel model(c);
  model.update({{{0}, 0, 1.0f, {1}, false}});
  auto info = model.tabularView()->query({0}, 0);
  EXPECT_FLOAT_EQ(info.reward, 50.0f);
  EXPECT_FLOAT_EQ(info.termProb, 1.0f);
  EXPECT_FLOAT_EQ(info.otherReward, 49.0f);
  model.update({{{0}, 0, 3.0f, {1}, false}, {{0}, 0, 100.0f, {2}, false}});
  info = model.tabularView()->query({0}, 0);
  EXPECT_FLOAT_EQ(info.reward, 2.0f);  // the third sample came after m: not counted
  EXPECT_EQ(model.tabularView()->visits({0}, 0), 2);
  model.setOptimistic(false);
  model.update({{{5}, 0, 0.0f, {5}, false}});
  EXPECT_FLOAT_EQ(model.tabularView()->query({5}, 0).termProb, 0.0f);
}

TEST(Rmax, LearnsTheTwoRoomGrid) {
  rl_agent::AgentOptions o;
  o.agent = "rmax";
  o.model = "tabular";
  o.explore = "unknown";
  o.planner = "vi";
  o.m = 5;
  o.reltrans = false;
  o.seed = 3;
  o.gamma = 0.95f;
  auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  ASSERT_NE(dynamic_cast<rl_agent::ModelBasedAgent*>(agent.get()), nullptr);
  test_mdps::TwoRoomGrid env;
  int total = 0, last = 0;
  for (int e = 0; e < 40; ++e) {
    last = test_mdps::runEpisode(*agent, env, 1000);
    total += last;
  }
  // Exploration is bounded: each of 31 cells x 4 actions is tried 5 times at most.
  EXPECT_LT(total, 31 * 4 * 5 + 40 * 10 + 200);
  EXPECT_EQ(last, 10);  // then the shortest path, every time (deterministic grid)
}
