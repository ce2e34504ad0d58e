// FuelRooms: movement, fuel rows and their costs (with and without --highvar), running out of
// fuel, the goal, the move noise, seeds.
#include "rl_env/env/fuel_rooms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using rl_common::State;
using rl_env::FuelRooms;

TEST(FuelRooms, Description) {
  const FuelRooms env(1, true, false);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 8);
  EXPECT_EQ(d.minFeatures, (std::vector<float>{0, 0, -1}));
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{20, 30, 60}));
  EXPECT_EQ(d.minReward, -400.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
}

TEST(FuelRooms, StartRanges) {
  FuelRooms env(3, true, false);
  for (int i = 0; i < 500; ++i) {
    env.reset();
    const State& s = env.sensation();
    EXPECT_GE(s[0], 7.0f);
    EXPECT_LE(s[0], 12.0f);
    EXPECT_LE(s[1], 4.0f);
    EXPECT_GE(s[2], 14.0f);
    EXPECT_LE(s[2], 18.0f);
  }
}

TEST(FuelRooms, CardinalAndDiagonalCosts) {
  FuelRooms env(1, false, false);
  env.setState({10, 10, 20});
  EXPECT_EQ(env.apply(FuelRooms::kEast), -1.0f);
  EXPECT_EQ(env.sensation(), (State{10, 11, 19}));
  EXPECT_FLOAT_EQ(env.apply(FuelRooms::kNorthEast), -1.4f);
  EXPECT_EQ(env.sensation(), (State{11, 12, 18}));
  EXPECT_FLOAT_EQ(env.apply(FuelRooms::kSouthWest), -1.4f);
  EXPECT_EQ(env.sensation(), (State{10, 11, 17}));
  // The edge stops the move but the step still costs fuel.
  env.setState({10, 0, 5});
  EXPECT_EQ(env.apply(FuelRooms::kWest), -1.0f);
  EXPECT_EQ(env.sensation(), (State{10, 0, 4}));
}

TEST(FuelRooms, FuelRowsRefuelAndCharge) {
  FuelRooms env(1, false, false);
  // Row 20: -10 - 8 - (ew % 5).
  env.setState({19, 7, 10});
  EXPECT_EQ(env.apply(FuelRooms::kNorth), -20.0f);
  EXPECT_EQ(env.sensation(), (State{20, 7, 29}));
  // Row 0: -13 - 8 - (ew % 5).
  env.setState({1, 3, 10});
  EXPECT_EQ(env.apply(FuelRooms::kSouth), -24.0f);
  EXPECT_EQ(env.sensation(), (State{0, 3, 29}));
  // The tank holds 60.
  env.setState({19, 5, 50});
  EXPECT_EQ(env.apply(FuelRooms::kNorth), -18.0f);
  EXPECT_EQ(env.sensation()[2], 60.0f);

  FuelRooms high(1, false, true);
  EXPECT_EQ(high.fuelCost(20, 7), -20.0f);  // -10 - 5 * 2
  EXPECT_EQ(high.fuelCost(0, 4), -33.0f);   // -13 - 5 * 4
  EXPECT_EQ(high.fuelCost(20, 5), -10.0f);
  EXPECT_EQ(env.fuelCost(0, 4), -25.0f);
}

TEST(FuelRooms, RunningOutOfFuelCostsFourHundredAndEnds) {
  FuelRooms env(1, false, false);
  env.setState({10, 10, 0});
  EXPECT_EQ(env.apply(FuelRooms::kEast), -400.0f);
  EXPECT_EQ(env.sensation(), (State{10, 11, -1}));
  EXPECT_TRUE(env.terminal());
  EXPECT_EQ(env.apply(FuelRooms::kEast), 0.0f);  // absorbing
}

TEST(FuelRooms, GoalEndsTheEpisodeWithZero) {
  FuelRooms env(1, false, false);
  env.setState({11, 23, 5});
  EXPECT_EQ(env.apply(FuelRooms::kEast), 0.0f);
  EXPECT_EQ(env.sensation(), (State{11, 24, 4}));
  EXPECT_TRUE(env.terminal());
}

TEST(FuelRooms, NoiseSlipsToTheNeighbouringMoves) {
  FuelRooms env(21, true, false);
  const int n = 20000;
  int intended = 0, left = 0, right = 0;
  for (int i = 0; i < n; ++i) {
    env.setState({10, 10, 30});
    env.apply(FuelRooms::kNorth);
    const State& s = env.sensation();
    if (s[0] == 11.0f && s[1] == 10.0f) ++intended;
    if (s[0] == 11.0f && s[1] == 9.0f) ++left;    // NW
    if (s[0] == 11.0f && s[1] == 11.0f) ++right;  // NE
  }
  EXPECT_EQ(intended + left + right, n);
  EXPECT_NEAR(static_cast<double>(intended) / n, 0.8, 4 * std::sqrt(0.8 * 0.2 / n));
  EXPECT_NEAR(static_cast<double>(left) / n, 0.1, 4 * std::sqrt(0.1 * 0.9 / n));
}

TEST(FuelRooms, FourSeedsGoalFuelFuelEmpty) {
  const FuelRooms env(5, true, false);
  const std::vector<rl_common::Experience> seeds = env.seedExperiences();
  ASSERT_EQ(seeds.size(), 4u);
  EXPECT_EQ(seeds[0].next[0], 11.0f);
  EXPECT_EQ(seeds[0].next[1], 24.0f);
  EXPECT_EQ(seeds[0].reward, 0.0f);
  EXPECT_TRUE(seeds[0].terminal);
  EXPECT_EQ(seeds[1].next[0], 20.0f);
  EXPECT_EQ(seeds[1].reward, env.fuelCost(20, static_cast<int>(seeds[1].next[1])));
  EXPECT_EQ(seeds[2].next[0], 0.0f);
  EXPECT_EQ(seeds[2].reward, env.fuelCost(0, static_cast<int>(seeds[2].next[1])));
  EXPECT_EQ(seeds[3].next[2], -1.0f);
  EXPECT_EQ(seeds[3].reward, -400.0f);
  EXPECT_TRUE(seeds[3].terminal);
  EXPECT_THROW(FuelRooms(1, true, false).apply(8), std::out_of_range);
}

}  // namespace
