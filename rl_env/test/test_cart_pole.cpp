// CartPole: the Barto et al. dynamics by hand, rewards, failure, clipping, seeds.
#include "rl_env/env/cart_pole.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "rl_common/random.h"

namespace {

using rl_common::State;
using rl_env::CartPole;

TEST(CartPole, Description) {
  const CartPole env(1, true);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 2);
  const float deg12 = static_cast<float>(12.0 * M_PI / 180.0);
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{2.5f, 3.0f, deg12, static_cast<float>(M_PI)}));
  EXPECT_EQ(d.minReward, 0.0f);
  EXPECT_EQ(d.maxReward, 1.0f);
}

TEST(CartPole, OneStepByHand) {
  CartPole env(1, false);
  EXPECT_EQ(env.sensation(), (State{0, 0, 0, 0}));
  // From rest with +10 N: temp = 10 / 1.1; thetaAcc = -temp / (0.5 (4/3 - 0.1 / 1.1));
  // xAcc = temp - 0.05 thetaAcc / 1.1. Euler: positions move with the old velocities.
  const double temp = 10.0 / 1.1;
  const double thetaAcc = -temp / (0.5 * (4.0 / 3.0 - 0.1 / 1.1));
  const double xAcc = temp - 0.05 * thetaAcc / 1.1;
  EXPECT_EQ(env.apply(CartPole::kRight), 1.0f);
  EXPECT_FLOAT_EQ(env.sensation()[0], 0.0f);
  EXPECT_FLOAT_EQ(env.sensation()[1], static_cast<float>(0.02 * xAcc));
  EXPECT_FLOAT_EQ(env.sensation()[2], 0.0f);
  EXPECT_FLOAT_EQ(env.sensation()[3], static_cast<float>(0.02 * thetaAcc));
  EXPECT_NEAR(0.02 * xAcc, 0.19512, 1e-4);
  EXPECT_NEAR(0.02 * thetaAcc, -0.29268, 1e-4);
}

TEST(CartPole, PoleFallingPastTwelveDegreesFails) {
  CartPole env(1, false);
  env.setState({0.0f, 0.0f, 0.2f, 1.0f});
  EXPECT_EQ(env.apply(CartPole::kLeft), 0.0f);
  EXPECT_TRUE(env.terminal());
  EXPECT_GT(env.physics()[2], CartPole::kFailAngle);
  // Agents see the angle clipped to the declared +-12 degrees.
  EXPECT_EQ(env.sensation()[2], static_cast<float>(CartPole::kFailAngle));
  EXPECT_EQ(env.apply(CartPole::kLeft), 0.0f);  // absorbing
}

TEST(CartPole, CartLeavingTheTrackFails) {
  CartPole env(1, false);
  env.setState({-2.38f, -2.0f, 0.0f, 0.0f});
  EXPECT_EQ(env.apply(CartPole::kLeft), 0.0f);
  EXPECT_TRUE(env.terminal());
  env.setState({2.0f, 0.0f, 0.0f, 0.0f});
  EXPECT_EQ(env.apply(CartPole::kLeft), 1.0f);
  EXPECT_FALSE(env.terminal());
}

TEST(CartPole, RandomPolicyFailsWithinAFewDozenSteps) {
  CartPole env(3, true);
  rl_common::Random actions(4);
  int episodes = 0, steps = 0;
  while (episodes < 50) {
    env.apply(actions.uniformInt(0, 1));
    ++steps;
    if (env.terminal()) {
      ++episodes;
      env.reset();
    }
  }
  EXPECT_LT(steps / episodes, 200);
}

TEST(CartPole, StochasticStartIsSmallAndRandom) {
  CartPole env(6, true);
  const State first = env.sensation();
  for (float v : first) EXPECT_LE(std::abs(v), 0.05f);
  env.reset();
  EXPECT_NE(env.sensation(), first);
}

TEST(CartPole, FourFailureSeeds) {
  const CartPole env(1, true);
  const std::vector<rl_common::Experience> seeds = env.seedExperiences();
  ASSERT_EQ(seeds.size(), 4u);
  for (const rl_common::Experience& e : seeds) {
    EXPECT_TRUE(e.terminal);
    EXPECT_EQ(e.reward, 0.0f);
  }
  EXPECT_THROW(CartPole(1, true).apply(2), std::out_of_range);
}

}  // namespace
