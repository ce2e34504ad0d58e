// FourRooms: Sutton et al.'s map, goal, start room, the exact model.
#include "rl_env/env/four_rooms.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "true_model_checks.h"

namespace {

using rl_common::Outcome;
using rl_common::State;
using rl_env::FourRooms;
using rl_env::Gridworld;

TEST(FourRooms, Description) {
  const FourRooms env(1, true);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 4);
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{10, 10}));
  EXPECT_EQ(d.minReward, -1.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
  EXPECT_TRUE(d.episodic);
}

TEST(FourRooms, SuttonPrecupSinghMap) {
  const Gridworld g = FourRooms::makeMap();
  int open = 0;
  for (int ns = 0; ns < 11; ++ns) {
    for (int ew = 0; ew < 11; ++ew) open += g.open(ns, ew) ? 1 : 0;
  }
  EXPECT_EQ(open, 104);
  // The four hallways.
  EXPECT_TRUE(g.open(8, 5));
  EXPECT_TRUE(g.open(1, 5));
  EXPECT_TRUE(g.open(5, 1));
  EXPECT_TRUE(g.open(4, 8));
  EXPECT_FALSE(g.open(5, 5));
  EXPECT_FALSE(g.open(5, 0));
  EXPECT_FALSE(g.open(4, 7));
  EXPECT_TRUE(g.open(5, 7));  // the north-east room reaches down to ns 5
  EXPECT_FALSE(g.wall(8, 4, Gridworld::kSouth));
  EXPECT_TRUE(g.wall(6, 0, Gridworld::kSouth));  // wall row ns 5 below the NW room
}

TEST(FourRooms, GoalAndStepRewards) {
  FourRooms env(1, false);
  env.setState({2, 10});
  EXPECT_EQ(env.apply(FourRooms::kNorth), -1.0f);
  EXPECT_EQ(env.sensation(), (State{3, 10}));
  env.setState({2, 10});
  EXPECT_EQ(env.apply(FourRooms::kSouth), 0.0f);
  EXPECT_TRUE(env.terminal());
  EXPECT_THROW(env.setState({5, 5}), std::invalid_argument);
}

TEST(FourRooms, StartsInTheNorthWestRoom) {
  FourRooms env(2, true);
  for (int i = 0; i < 500; ++i) {
    env.reset();
    EXPECT_GE(env.sensation()[0], 6.0f);
    EXPECT_LE(env.sensation()[1], 4.0f);
  }
}

TEST(FourRoomsTrueModel, DistributionsAndSampling) {
  FourRooms env(3, true);
  // In the hallway (8,5): east 0.8, north/south blocked by the wall column: stay 0.2.
  const std::vector<Outcome> out = env.transitions({8, 5}, FourRooms::kEast);
  ASSERT_EQ(out.size(), 2u);
  rl_env_test::expectDistribution(out, "hallway");
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {8, 6}), 0.8);
  EXPECT_NEAR(rl_env_test::probabilityOf(out, {8, 5}), 0.2, 1e-12);
  rl_env_test::expectSamplingAgrees(env, {8, 5}, FourRooms::kEast, 20000);
  rl_env_test::expectSamplingAgrees(env, {7, 2}, FourRooms::kSouth, 20000);
}

TEST(FourRoomsTrueModel, ReachableStatesClosedAndComplete) {
  const FourRooms env(1, true);
  std::vector<State> starts;
  for (int ns = 6; ns <= 10; ++ns) {
    for (int ew = 0; ew <= 4; ++ew)
      starts.push_back({static_cast<float>(ns), static_cast<float>(ew)});
  }
  rl_env_test::expectReachableClosed(env, starts);
  EXPECT_EQ(env.reachableStates().size(), 104u);
}

}  // namespace
