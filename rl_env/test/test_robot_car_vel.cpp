// RobotCarVel: tasks, pedal actions, reward before the dynamics, the car's response, the brake
// lag, seeds.
#include "rl_env/env/robot_car_vel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace {

using rl_common::State;
using rl_env::RobotCarVel;
using Task = RobotCarVel::Task;

TEST(RobotCarVel, DescriptionAndStarts) {
  const RobotCarVel up(1, Task::kUp2To7, false);
  const rl_common::EnvironmentDescription d = up.describe();
  EXPECT_EQ(d.numActions, 5);
  EXPECT_EQ(d.maxFeatures, (std::vector<float>{12, 12, 0.4f, 1}));
  EXPECT_EQ(d.minReward, -120.0f);
  EXPECT_EQ(d.maxReward, 0.0f);
  EXPECT_TRUE(d.episodic);
  EXPECT_EQ(up.sensation(), (State{7, 2, 0, 0}));
  EXPECT_EQ(RobotCarVel(1, Task::kDown7To2, false).sensation(), (State{2, 7, 0, 0}));
  RobotCarVel random(3, Task::kRandom, false);
  for (int i = 0; i < 200; ++i) {
    random.reset();
    const State& s = random.sensation();
    EXPECT_EQ(s[0], std::floor(s[0]));
    EXPECT_LE(s[0], 11.0f);
    EXPECT_LE(s[1], 11.0f);
  }
}

TEST(RobotCarVel, RewardIsComputedBeforeTheDynamics) {
  RobotCarVel env(1, Task::kUp2To7, false);
  EXPECT_EQ(env.apply(RobotCarVel::kThrottleUp), -50.0f);  // |2 - 7| * 10 before moving
  EXPECT_FALSE(env.terminal());
}

TEST(RobotCarVel, PedalTargetsMoveInTenthsWithinTheirRanges) {
  RobotCarVel env(1, Task::kUp2To7, false);
  for (int i = 0; i < 6; ++i) env.apply(RobotCarVel::kThrottleUp);
  EXPECT_EQ(env.sensation()[2], 0.4f);
  env.apply(RobotCarVel::kThrottleDown);
  EXPECT_EQ(env.sensation()[2], 0.3f);
  for (int i = 0; i < 12; ++i) env.apply(RobotCarVel::kBrakeUp);
  EXPECT_EQ(env.sensation()[3], 1.0f);
  for (int i = 0; i < 3; ++i) env.apply(RobotCarVel::kBrakeDown);
  EXPECT_EQ(env.sensation()[3], 0.7f);
  for (int i = 0; i < 12; ++i) env.apply(RobotCarVel::kBrakeDown);
  EXPECT_EQ(env.sensation()[3], 0.0f);
}

TEST(RobotCarVel, ThrottleAcceleratesBrakeDecelerates) {
  RobotCarVel env(1, Task::kUp2To7, false);
  for (int i = 0; i < 4; ++i) env.apply(RobotCarVel::kThrottleUp);
  for (int i = 0; i < 20; ++i) env.apply(RobotCarVel::kNothing);
  const float fast = env.sensation()[1];
  EXPECT_GT(fast, 5.0f);  // about 2 s at up to 2.4 m/s^2 minus drag
  for (int i = 0; i < 400; ++i) env.apply(RobotCarVel::kNothing);
  EXPECT_NEAR(env.sensation()[1], 12.0f, 0.01f);  // full throttle holds 12 m/s
  for (int i = 0; i < 4; ++i) env.apply(RobotCarVel::kThrottleDown);
  for (int i = 0; i < 10; ++i) env.apply(RobotCarVel::kBrakeUp);
  for (int i = 0; i < 40; ++i) env.apply(RobotCarVel::kNothing);
  EXPECT_EQ(env.sensation()[1], 0.0f);  // braked to a stop, never negative
}

TEST(RobotCarVel, LagSlowsTheBrake) {
  RobotCarVel plain(1, Task::kDown7To2, false);
  RobotCarVel lagged(1, Task::kDown7To2, true);
  for (int i = 0; i < 10; ++i) {
    plain.apply(RobotCarVel::kBrakeUp);
    lagged.apply(RobotCarVel::kBrakeUp);
  }
  EXPECT_LT(lagged.physics().brake, plain.physics().brake);
  EXPECT_GT(lagged.sensation()[1], plain.sensation()[1]);
  for (int i = 0; i < 40; ++i) lagged.apply(RobotCarVel::kNothing);
  EXPECT_NEAR(lagged.physics().brake, 1.0, 0.01);  // it gets there
}

TEST(RobotCarVel, TwentyFiveSeeds) {
  const RobotCarVel env(2, Task::kUp2To7, false);
  const std::vector<rl_common::Experience> seeds = env.seedExperiences();
  ASSERT_EQ(seeds.size(), 25u);
  for (const rl_common::Experience& e : seeds) {
    EXPECT_FALSE(e.terminal);
    EXPECT_EQ(e.s[0], 7.0f);
    EXPECT_FLOAT_EQ(e.reward, -10.0f * std::abs(e.s[1] - e.s[0]));
    // Replaying the seed from its state reproduces it (pedals start at their targets).
    RobotCarVel replay(2, Task::kUp2To7, false);
    replay.setState(e.s);
    EXPECT_FLOAT_EQ(replay.apply(e.action), e.reward);
    EXPECT_EQ(replay.sensation(), e.next);
  }
  EXPECT_THROW(RobotCarVel(1, Task::kUp2To7, false).apply(5), std::out_of_range);
}

}  // namespace
