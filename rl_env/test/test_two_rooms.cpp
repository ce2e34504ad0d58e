// TwoRooms: the wall and doorway, goal reward, the action delay, seeds, the exact model.
#include "rl_env/env/two_rooms.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "true_model_checks.h"

namespace {

using rl_common::Outcome;
using rl_common::State;
using rl_env::TwoRooms;

TEST(TwoRooms, Description) {
  const TwoRooms env(1, true, 0);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 4);
  EXPECT_EQ(d.minFeatures, (std::vector<float>{0, 0}));
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{4, 10}));
  EXPECT_EQ(d.minReward, -1.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
  EXPECT_TRUE(d.episodic);
  EXPECT_THROW(TwoRooms(1, true, -1), std::invalid_argument);
}

TEST(TwoRooms, OnlyTheDoorwayCrossesTheWall) {
  TwoRooms env(1, false, 0);
  env.setState({1, 4});
  EXPECT_EQ(env.apply(TwoRooms::kEast), -1.0f);
  EXPECT_EQ(env.sensation(), (State{1, 4}));
  env.setState({2, 4});
  env.apply(TwoRooms::kEast);
  EXPECT_EQ(env.sensation(), (State{2, 5}));
  env.apply(TwoRooms::kNorth);  // the doorway has wall above and below
  EXPECT_EQ(env.sensation(), (State{2, 5}));
  env.apply(TwoRooms::kEast);
  EXPECT_EQ(env.sensation(), (State{2, 6}));
  EXPECT_THROW(env.setState({0, 5}), std::invalid_argument);
}

TEST(TwoRooms, GoalGivesZeroAndEndsTheEpisode) {
  TwoRooms env(1, false, 0);
  env.setState({1, 2});
  EXPECT_EQ(env.apply(TwoRooms::kWest), 0.0f);
  EXPECT_EQ(env.sensation(), (State{1, 1}));
  EXPECT_TRUE(env.terminal());
  EXPECT_EQ(env.apply(TwoRooms::kEast), 0.0f);  // absorbing
  EXPECT_EQ(env.sensation(), (State{1, 1}));
}

TEST(TwoRooms, StartsInTheRightRoom) {
  TwoRooms env(9, true, 0);
  for (int i = 0; i < 500; ++i) {
    env.reset();
    EXPECT_GE(env.sensation()[1], 6.0f);
    EXPECT_FALSE(env.terminal());
  }
}

TEST(TwoRooms, DelayedActionsTakeEffectKStepsLater) {
  TwoRooms env(1, false, 2);
  env.setState({2, 8});
  // The first two steps execute nothing (and cost -1 like any step).
  EXPECT_EQ(env.apply(TwoRooms::kWest), -1.0f);
  EXPECT_EQ(env.sensation(), (State{2, 8}));
  EXPECT_EQ(env.apply(TwoRooms::kWest), -1.0f);
  EXPECT_EQ(env.sensation(), (State{2, 8}));
  env.apply(TwoRooms::kNorth);  // executes the first WEST
  EXPECT_EQ(env.sensation(), (State{2, 7}));
  env.apply(TwoRooms::kNorth);  // the second WEST
  EXPECT_EQ(env.sensation(), (State{2, 6}));
  env.apply(TwoRooms::kNorth);  // the first NORTH
  EXPECT_EQ(env.sensation(), (State{3, 6}));
  EXPECT_TRUE(env.seedExperiences().empty());
  EXPECT_THROW(env.transitions({2, 8}, 0), std::runtime_error);
  EXPECT_THROW(env.reachableStates(), std::runtime_error);
}

TEST(TwoRooms, TwoSeedsGoalAndDoorway) {
  const TwoRooms env(1, true, 0);
  const std::vector<rl_common::Experience> seeds = env.seedExperiences();
  ASSERT_EQ(seeds.size(), 2u);
  EXPECT_EQ(seeds[0].s, (State{1, 2}));
  EXPECT_EQ(seeds[0].action, TwoRooms::kWest);
  EXPECT_EQ(seeds[0].next, (State{1, 1}));
  EXPECT_EQ(seeds[0].reward, 0.0f);
  EXPECT_TRUE(seeds[0].terminal);
  EXPECT_EQ(seeds[1].s, (State{2, 6}));
  EXPECT_EQ(seeds[1].next, (State{2, 5}));
  EXPECT_EQ(seeds[1].reward, -1.0f);
  EXPECT_FALSE(seeds[1].terminal);
}

TEST(TwoRoomsTrueModel, DistributionsAndSampling) {
  TwoRooms env(4, true, 0);
  const std::vector<Outcome> out = env.transitions({2, 6}, TwoRooms::kWest);
  ASSERT_EQ(out.size(), 3u);
  rl_env_test::expectDistribution(out, "west");
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {2, 5}), 0.8);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {3, 6}), 0.1);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {1, 6}), 0.1);
  // Next to the goal: 0.8 into the goal (reward 0, terminal).
  const std::vector<Outcome> toGoal = env.transitions({2, 1}, TwoRooms::kSouth);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(toGoal, {1, 1}), 0.8);
  for (const Outcome& o : toGoal) {
    EXPECT_EQ(o.terminal, o.next == State({1, 1}));
    EXPECT_EQ(o.reward, o.terminal ? 0.0f : -1.0f);
  }
  rl_env_test::expectSamplingAgrees(env, {2, 6}, TwoRooms::kWest, 20000);
  rl_env_test::expectSamplingAgrees(env, {2, 5}, TwoRooms::kNorth, 20000);
}

TEST(TwoRoomsTrueModel, ReachableStatesClosedAndComplete) {
  const TwoRooms env(1, true, 0);
  EXPECT_EQ(env.reachableStates().size(), 51u);
  std::vector<State> starts;
  for (int ns = 0; ns < 5; ++ns) {
    for (int ew = 6; ew < 11; ++ew)
      starts.push_back({static_cast<float>(ns), static_cast<float>(ew)});
  }
  rl_env_test::expectReachableClosed(env, starts);
}

}  // namespace
