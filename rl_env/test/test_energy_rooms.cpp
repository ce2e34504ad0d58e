// EnergyRooms: recharge squares (the HEAD list), energy drain and floor, rewards, the goal.
#include "rl_env/env/energy_rooms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "rl_env/env/four_rooms.h"

namespace {

using rl_common::State;
using rl_env::EnergyRooms;

TEST(EnergyRooms, Description) {
  const EnergyRooms env(1, true);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 4);
  EXPECT_EQ(d.minFeatures, (std::vector<float>{0, 0, 0}));
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{10, 10, 20}));
  EXPECT_EQ(d.minReward, -2.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
  EXPECT_EQ(env.sensation()[2], 10.0f);  // starts with 10
}

TEST(EnergyRooms, RechargeSquaresAreTheHeadListAndOpenCells) {
  const auto& squares = EnergyRooms::rechargeSquares();
  const std::vector<std::pair<int, int>> expected = {{7, 3}, {7, 7}, {3, 3}, {3, 7}};
  const std::vector<std::pair<int, int>> listed(squares.begin(), squares.end());
  EXPECT_EQ(listed, expected);
  const rl_env::Gridworld map = rl_env::FourRooms::makeMap();
  for (const auto& [ns, ew] : squares) EXPECT_TRUE(map.open(ns, ew));
}

TEST(EnergyRooms, RechargeHappensBeforeTheMove) {
  EnergyRooms env(1, false);
  for (const auto& [ns, ew] : EnergyRooms::rechargeSquares()) {
    env.setState({static_cast<float>(ns), static_cast<float>(ew), 2});
    EXPECT_EQ(env.apply(EnergyRooms::kWest), -1.0f);
    EXPECT_EQ(env.sensation(), (State{static_cast<float>(ns), static_cast<float>(ew - 1), 10}));
  }
}

TEST(EnergyRooms, EnergyDrainsToZeroThenCostsTwo) {
  EnergyRooms env(1, false);
  env.setState({8, 1, 2});
  EXPECT_EQ(env.apply(EnergyRooms::kEast), -1.0f);
  EXPECT_EQ(env.sensation(), (State{8, 2, 1}));
  EXPECT_EQ(env.apply(EnergyRooms::kWest), -2.0f);  // energy 0 now
  EXPECT_EQ(env.sensation(), (State{8, 1, 0}));
  EXPECT_EQ(env.apply(EnergyRooms::kWest), -2.0f);  // floored at 0
  EXPECT_EQ(env.sensation(), (State{8, 0, 0}));
}

TEST(EnergyRooms, GoalGivesZeroAndEndsTheEpisode) {
  EnergyRooms env(1, false);
  env.setState({2, 10, 0});
  EXPECT_EQ(env.apply(EnergyRooms::kSouth), 0.0f);
  EXPECT_TRUE(env.terminal());
  EXPECT_EQ(env.apply(EnergyRooms::kNorth), 0.0f);
  EXPECT_EQ(env.sensation(), (State{1, 10, 0}));
}

TEST(EnergyRooms, StochasticDrainHappensWithProbabilityPoint8) {
  EnergyRooms env(12, true);
  const int n = 20000;
  int drained = 0;
  for (int i = 0; i < n; ++i) {
    env.setState({8, 2, 5});
    env.apply(EnergyRooms::kNorth);
    drained += env.sensation()[2] == 4.0f ? 1 : 0;
  }
  EXPECT_NEAR(static_cast<double>(drained) / n, 0.8, 4 * std::sqrt(0.8 * 0.2 / n));
}

TEST(EnergyRooms, SetStateValidates) {
  EnergyRooms env(1, true);
  EXPECT_THROW(env.setState({5, 5, 3}), std::invalid_argument);   // wall
  EXPECT_THROW(env.setState({8, 2, 21}), std::invalid_argument);  // energy above 20
  EXPECT_THROW(env.setState({8, 2}), std::invalid_argument);
  EXPECT_THROW(env.apply(4), std::out_of_range);
}

}  // namespace
