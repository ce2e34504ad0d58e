// Stocks: layout, ownership flips, the deterministic and stochastic price rules, rewards.
#include "rl_env/env/stocks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using rl_common::State;
using rl_env::Stocks;

TEST(Stocks, DescriptionFollowsTheSectorCounts) {
  const Stocks env(1, true, 3, 3);
  const rl_common::EnvironmentDescription d = env.describe();
  EXPECT_EQ(d.numActions, 4);
  EXPECT_EQ(d.numFeatures(), 12u);
  EXPECT_EQ(d.minReward, -9.0f);
  EXPECT_EQ(d.maxReward, 9.0f);
  EXPECT_FALSE(d.episodic);
  const Stocks small(1, true, 2, 4);
  EXPECT_EQ(small.numActions(), 3);
  EXPECT_EQ(small.sensation().size(), 10u);
  EXPECT_EQ(small.risingIndex(1, 2), 2 + 4 + 2);
  EXPECT_THROW(Stocks(1, true, 0, 3), std::invalid_argument);
  EXPECT_THROW(Stocks(1, true, 3, 0), std::invalid_argument);
  EXPECT_THROW(Stocks(1, true, 1000, 1000), std::invalid_argument);  // 1,001,000 features
  EXPECT_NO_THROW(Stocks(1, true, 256, 255));                        // 65,536
}

// 2 sectors of 3 stocks: sector 0 owned with 2 of 3 rising, sector 1 not owned with 1 rising.
const State kStart = {1, 0, /*sector 0*/ 1, 1, 0, /*sector 1*/ 1, 0, 0};

TEST(Stocks, DeterministicRuleAndRewardsByHand) {
  // Rise probabilities: sector 0: 0.1 + 0.8 * 2/3 = 0.633 > 0.5 (all rise); sector 1:
  // 0.1 + 0.8 / 3 = 0.367 (all fall).
  Stocks env(1, false, 2, 3);
  env.setState(kStart);
  EXPECT_NEAR(env.riseProbability(0), 0.1 + 0.8 * 2 / 3.0, 1e-12);
  EXPECT_EQ(env.apply(2), 3.0f);  // do nothing: owned sector 0 has 3 rising stocks
  EXPECT_EQ(env.sensation(), (State{1, 0, 1, 1, 1, 0, 0, 0}));

  env.setState(kStart);
  EXPECT_EQ(env.apply(1), 0.0f);  // buy sector 1: +3 from sector 0, -3 from sector 1
  EXPECT_EQ(env.sensation(), (State{1, 1, 1, 1, 1, 0, 0, 0}));

  env.setState(kStart);
  EXPECT_EQ(env.apply(0), 0.0f);  // sell sector 0: nothing owned
  EXPECT_EQ(env.sensation()[0], 0.0f);
}

TEST(Stocks, StochasticRiseFrequenciesMatchTheRule) {
  Stocks env(9, true, 2, 3);
  const int n = 20000;
  int rise0 = 0, rise1 = 0;
  double rewardSum = 0.0;
  for (int i = 0; i < n; ++i) {
    env.setState(kStart);
    rewardSum += env.apply(2);
    rise0 += env.sensation()[2] > 0.5f ? 1 : 0;
    rise1 += env.sensation()[5] > 0.5f ? 1 : 0;
  }
  const double p0 = 0.1 + 0.8 * 2 / 3.0;
  const double p1 = 0.1 + 0.8 / 3.0;
  EXPECT_NEAR(static_cast<double>(rise0) / n, p0, 4 * std::sqrt(p0 * (1 - p0) / n));
  EXPECT_NEAR(static_cast<double>(rise1) / n, p1, 4 * std::sqrt(p1 * (1 - p1) / n));
  // Expected reward: 3 owned stocks, each +1 w.p. p0 and -1 otherwise: 3 (2 p0 - 1).
  const double mean = 3 * (2 * p0 - 1);
  const double sd = std::sqrt(3 * 4 * p0 * (1 - p0) / n);
  EXPECT_NEAR(rewardSum / n, mean, 4 * sd);
}

TEST(Stocks, NeverTerminalAndSetStateValidates) {
  Stocks env(1, true, 3, 3);
  for (int i = 0; i < 100; ++i) {
    env.apply(i % 4);
    EXPECT_FALSE(env.terminal());
  }
  EXPECT_THROW(env.setState(State(11, 0.0f)), std::invalid_argument);
  EXPECT_THROW(env.setState(State(12, 2.0f)), std::invalid_argument);
  EXPECT_THROW(env.apply(4), std::out_of_range);
}

}  // namespace
