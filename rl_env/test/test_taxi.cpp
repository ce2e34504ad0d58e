// Taxi: walls, pickup/putdown rewards, delivery, the fickle passenger, the exact model.
#include "rl_env/env/taxi.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

#include "true_model_checks.h"

namespace {

using rl_common::Outcome;
using rl_common::State;
using rl_env::Gridworld;
using rl_env::Taxi;

TEST(Taxi, Description) {
  const Taxi env(1, true);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 6);
  EXPECT_EQ(d.minFeatures, (std::vector<float>{0, 0, 0, 0}));
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{4, 4, 4, 3}));
  EXPECT_EQ(d.minReward, -10.0f);
  EXPECT_EQ(d.maxReward, 20.0f);
  EXPECT_TRUE(d.episodic);
  EXPECT_TRUE(env.seedExperiences().empty());
}

TEST(Taxi, DietterichWalls) {
  const Taxi env(1, true);
  const Gridworld& g = env.grid();
  for (int ns : {0, 1}) {
    EXPECT_TRUE(g.wall(ns, 0, Gridworld::kEast));
    EXPECT_TRUE(g.wall(ns, 1, Gridworld::kWest));
    EXPECT_TRUE(g.wall(ns, 2, Gridworld::kEast));
    EXPECT_TRUE(g.wall(ns, 3, Gridworld::kWest));
    EXPECT_FALSE(g.wall(ns, 1, Gridworld::kEast));
  }
  for (int ns : {3, 4}) {
    EXPECT_TRUE(g.wall(ns, 1, Gridworld::kEast));
    EXPECT_FALSE(g.wall(ns, 0, Gridworld::kEast));
  }
  EXPECT_FALSE(g.wall(2, 0, Gridworld::kEast));
  EXPECT_FALSE(g.wall(2, 2, Gridworld::kEast));
  EXPECT_TRUE(g.wall(4, 2, Gridworld::kNorth));  // the grid's edge
}

TEST(Taxi, MovesCostOneAndStopAtWalls) {
  Taxi env(1, false);
  env.setState({0, 0, 1, 2});
  EXPECT_EQ(env.apply(Taxi::kEast), -1.0f);  // wall between columns 0|1
  EXPECT_EQ(env.sensation(), (State{0, 0, 1, 2}));
  EXPECT_EQ(env.apply(Taxi::kNorth), -1.0f);  // NORTH is ns + 1
  EXPECT_EQ(env.sensation(), (State{1, 0, 1, 2}));
  env.setState({2, 0, 1, 2});
  EXPECT_EQ(env.apply(Taxi::kEast), -1.0f);
  EXPECT_EQ(env.sensation(), (State{2, 1, 1, 2}));
}

TEST(Taxi, IllegalPickupAndPutdownCostTen) {
  Taxi env(1, true);
  env.setState({2, 2, 0, 1});  // passenger at (4,0), taxi elsewhere
  EXPECT_EQ(env.apply(Taxi::kPickup), -10.0f);
  EXPECT_EQ(env.sensation(), (State{2, 2, 0, 1}));
  env.setState({0, 3, 0, 1});  // on landmark 1, passenger at landmark 0
  EXPECT_EQ(env.apply(Taxi::kPickup), -10.0f);
  EXPECT_EQ(env.apply(Taxi::kPutdown), -10.0f);  // no passenger aboard
  env.setState({4, 4, Taxi::kInTaxi, 1});        // aboard, on landmark 2, destination 1
  EXPECT_EQ(env.apply(Taxi::kPutdown), -10.0f);
  EXPECT_EQ(env.sensation(), (State{4, 4, 4, 1}));
  EXPECT_FALSE(env.terminal());
}

TEST(Taxi, LegalPickupThenCorrectPutdownEndsTheEpisodeWithTwenty) {
  Taxi env(1, false);
  env.setState({4, 0, 0, 3});  // on landmark 0 with the passenger there, destination (0,0)
  EXPECT_EQ(env.apply(Taxi::kPickup), -1.0f);
  EXPECT_EQ(env.sensation(), (State{4, 0, 4, 3}));
  for (int i = 0; i < 4; ++i) EXPECT_EQ(env.apply(Taxi::kSouth), -1.0f);
  EXPECT_EQ(env.sensation(), (State{0, 0, 4, 3}));
  EXPECT_FALSE(env.terminal());
  EXPECT_EQ(env.apply(Taxi::kPutdown), 20.0f);
  EXPECT_EQ(env.sensation(), (State{0, 0, 3, 3}));
  EXPECT_TRUE(env.terminal());
  // Terminal states are absorbing until reset.
  EXPECT_EQ(env.apply(Taxi::kNorth), 0.0f);
  EXPECT_EQ(env.sensation(), (State{0, 0, 3, 3}));
  env.reset();
  EXPECT_FALSE(env.terminal());
}

TEST(Taxi, ResetPutsPassengerAndDestinationOnDifferentLandmarks) {
  Taxi env(5, true);
  std::set<State> seen;
  for (int i = 0; i < 2000; ++i) {
    env.reset();
    const State& s = env.sensation();
    EXPECT_LT(s[2], 4.0f);
    EXPECT_NE(s[2], s[3]);
    seen.insert(s);
  }
  EXPECT_EQ(seen.size(), 300u);  // 25 cells x 12 (passenger, destination) pairs
}

TEST(Taxi, FicklePassengerChangesDestinationOnTheFirstMoveOnly) {
  Taxi env(77, true);
  const int n = 20000;
  int changed = 0;
  int changedLater = 0;
  for (int i = 0; i < n; ++i) {
    env.setState({4, 4, 2, 0});  // passenger on landmark 2 (4,4), destination 0
    env.apply(Taxi::kPickup);
    env.apply(Taxi::kWest);
    const float dest = env.sensation()[3];
    if (dest != 0.0f) ++changed;
    env.apply(Taxi::kWest);
    if (env.sensation()[3] != dest) ++changedLater;
  }
  const double sd = std::sqrt(0.3 * 0.7 / n);
  EXPECT_NEAR(static_cast<double>(changed) / n, 0.3, 4 * sd);
  EXPECT_EQ(changedLater, 0);

  Taxi deterministic(77, false);
  for (int i = 0; i < 200; ++i) {
    deterministic.setState({4, 4, 2, 0});
    deterministic.apply(Taxi::kPickup);
    deterministic.apply(Taxi::kWest);
    EXPECT_EQ(deterministic.sensation()[3], 0.0f);
  }
}

TEST(TaxiTrueModel, MoveDistributionsByHand) {
  const Taxi env(1, true);
  // From (2,2) north: (3,2) 0.8, (2,3) 0.1, (2,1) 0.1.
  std::vector<Outcome> out = env.transitions({2, 2, 0, 1}, Taxi::kNorth);
  ASSERT_EQ(out.size(), 3u);
  rl_env_test::expectDistribution(out, "north");
  for (const Outcome& o : out) EXPECT_EQ(o.reward, -1.0f);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {3, 2, 0, 1}), 0.8);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {2, 3, 0, 1}), 0.1);
  EXPECT_DOUBLE_EQ(rl_env_test::probabilityOf(out, {2, 1, 0, 1}), 0.1);
  // From (0,0) east: the wall and the south edge both keep the taxi: stay 0.9, north 0.1.
  out = env.transitions({0, 0, 0, 1}, Taxi::kEast);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_NEAR(rl_env_test::probabilityOf(out, {0, 0, 0, 1}), 0.9, 1e-12);
  EXPECT_NEAR(rl_env_test::probabilityOf(out, {1, 0, 0, 1}), 0.1, 1e-12);
  // Delivery: one terminal outcome with +20.
  out = env.transitions({0, 3, 4, 1}, Taxi::kPutdown);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].next, (State{0, 3, 1, 1}));
  EXPECT_EQ(out[0].reward, 20.0f);
  EXPECT_TRUE(out[0].terminal);
  // A terminal state is absorbing.
  out = env.transitions({0, 3, 1, 1}, Taxi::kNorth);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].next, (State{0, 3, 1, 1}));
  EXPECT_EQ(out[0].reward, 0.0f);
  EXPECT_THROW(env.transitions({0, 2, 1, 1}, Taxi::kNorth), std::invalid_argument);
  EXPECT_THROW(env.transitions({0, 2, 5, 1}, Taxi::kNorth), std::invalid_argument);
  EXPECT_THROW(env.transitions({0, 2, 0, 1}, 6), std::out_of_range);
}

TEST(TaxiTrueModel, SamplingAgrees) {
  Taxi env(31, true);
  rl_env_test::expectSamplingAgrees(env, {2, 2, 0, 1}, Taxi::kNorth, 20000);
  rl_env_test::expectSamplingAgrees(env, {0, 0, 4, 1}, Taxi::kEast, 20000);
  rl_env_test::expectSamplingAgrees(env, {3, 1, 4, 1}, Taxi::kWest, 20000);
}

TEST(TaxiTrueModel, ReachableStatesClosedAndComplete) {
  for (bool stochastic : {true, false}) {
    const Taxi env(1, stochastic);
    const std::vector<State> all = env.reachableStates();
    EXPECT_EQ(all.size(), 25u * 16u + 4u);
    std::vector<State> starts;
    for (int ns = 0; ns < 5; ++ns) {
      for (int ew = 0; ew < 5; ++ew) {
        for (int p = 0; p < 4; ++p) {
          for (int d = 0; d < 4; ++d) {
            if (p != d) {
              starts.push_back({static_cast<float>(ns), static_cast<float>(ew),
                                static_cast<float>(p), static_cast<float>(d)});
            }
          }
        }
      }
    }
    rl_env_test::expectReachableClosed(env, starts);
  }
}

}  // namespace
