// MountainCar: the HEAD dynamics (position uses the new velocity), start states, the goal, the
// left end, the observation delay, seeds.
#include "rl_env/env/mountain_car.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using rl_common::State;
using rl_env::MountainCar;

TEST(MountainCar, Description) {
  const MountainCar env(1, true, 0);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 3);
  EXPECT_EQ(d.minFeatures, (std::vector<float>{-1.2f, -0.07f}));
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{0.6f, 0.07f}));
  EXPECT_EQ(d.minReward, -1.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
  EXPECT_THROW(MountainCar(1, true, -2), std::invalid_argument);
}

TEST(MountainCar, DeterministicStartIsTheOrigin) {
  MountainCar env(1, false, 0);
  EXPECT_EQ(env.sensation(), (State{0.0f, 0.0f}));
  env.apply(2);
  env.reset();
  EXPECT_EQ(env.sensation(), (State{0.0f, 0.0f}));
}

TEST(MountainCar, StochasticStartIsUniform) {
  MountainCar env(4, true, 0);
  double sumPos = 0.0;
  const int n = 4000;
  for (int i = 0; i < n; ++i) {
    env.reset();
    const State& s = env.sensation();
    EXPECT_GE(s[0], -1.2f);
    EXPECT_LT(s[0], 0.59f);
    EXPECT_GE(s[1], -0.07f);
    EXPECT_LE(s[1], 0.07f);
    sumPos += s[0];
  }
  // Mean of U(-1.2, 0.59) is -0.305; sd of the mean is 1.79 / sqrt(12 n).
  EXPECT_NEAR(sumPos / n, -0.305, 4 * 1.79 / std::sqrt(12.0 * n));
}

TEST(MountainCar, PositionUsesTheNewVelocity) {
  MountainCar env(1, false, 0);
  // From (0, 0) pushing right: v = 0.001 - 0.0025 cos(0) = -0.0015, then x = 0 + v.
  EXPECT_EQ(env.apply(2), -1.0f);
  EXPECT_FLOAT_EQ(env.sensation()[1], -0.0015f);
  EXPECT_FLOAT_EQ(env.sensation()[0], -0.0015f);
  // Next step from (-0.0015, -0.0015) coasting.
  const double v = -0.0015 - 0.0025 * std::cos(3 * -0.0015);
  env.apply(1);
  EXPECT_FLOAT_EQ(env.sensation()[1], static_cast<float>(v));
  EXPECT_FLOAT_EQ(env.sensation()[0], static_cast<float>(-0.0015 + v));
}

TEST(MountainCar, ReachingTheGoalGivesZeroAndEnds) {
  MountainCar env(1, false, 0);
  env.setState({0.59f, 0.02f});
  EXPECT_EQ(env.apply(1), 0.0f);
  EXPECT_TRUE(env.terminal());
  EXPECT_EQ(env.sensation()[0], 0.6f);
  EXPECT_EQ(env.apply(2), 0.0f);  // absorbing
}

TEST(MountainCar, LeftEndStopsTheCar) {
  MountainCar env(1, false, 0);
  env.setState({-1.19f, -0.07f});
  EXPECT_EQ(env.apply(0), -1.0f);
  EXPECT_EQ(env.sensation(), (State{-1.2f, 0.0f}));
}

TEST(MountainCar, VelocityIsClipped) {
  MountainCar env(1, false, 0);
  env.setState({-0.5f, 0.07f});
  env.apply(2);
  EXPECT_LE(env.sensation()[1], 0.07f);
}

TEST(MountainCar, DelayShowsTheStateOfKStepsAgo) {
  MountainCar delayed(1, false, 2);
  MountainCar direct(1, false, 0);
  std::vector<State> truth{direct.sensation()};
  for (int i = 0; i < 6; ++i) {
    delayed.apply(2);
    direct.apply(2);
    truth.push_back(direct.sensation());
    EXPECT_EQ(delayed.trueState(), truth.back());
    EXPECT_EQ(delayed.sensation(), truth[truth.size() - 1 - std::min<std::size_t>(2, i + 1)]);
  }
  EXPECT_TRUE(delayed.seedExperiences().empty());
}

TEST(MountainCar, FourSeeds) {
  const MountainCar env(1, true, 0);
  const std::vector<rl_common::Experience> seeds = env.seedExperiences();
  ASSERT_EQ(seeds.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_TRUE(seeds[static_cast<std::size_t>(i)].terminal);
    EXPECT_EQ(seeds[static_cast<std::size_t>(i)].reward, 0.0f);
    EXPECT_EQ(seeds[static_cast<std::size_t>(i)].next[0], 0.6f);
  }
  EXPECT_FALSE(seeds[3].terminal);
  EXPECT_EQ(seeds[3].reward, -1.0f);
  EXPECT_EQ(seeds[3].next, (State{-1.2f, 0.0f}));
}

TEST(MountainCar, StochasticForceNoiseChangesTheStep) {
  MountainCar env(8, true, 0);
  std::vector<float> velocities;
  for (int i = 0; i < 200; ++i) {
    env.setState({0.0f, 0.0f});
    env.apply(1);
    velocities.push_back(env.sensation()[1]);
  }
  // v = 0.001 U(-0.5, 0.5) - 0.0025: within [-0.003, -0.002], not constant.
  const auto [lo, hi] = std::minmax_element(velocities.begin(), velocities.end());
  EXPECT_GE(*lo, -0.0030001f);
  EXPECT_LE(*hi, -0.0019999f);
  EXPECT_GT(*hi - *lo, 0.0008f);
}

}  // namespace
