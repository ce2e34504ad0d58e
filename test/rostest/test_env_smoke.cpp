// Acts as a minimal agent against the env node: the latched description arrives, the first
// state follows once we listen, and an action is answered with a new state.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(EnvSmoke, LightWorldDescriptionFirstStateAndAStep) {
  ros::NodeHandle nh;
  std::vector<rl_msgs::RLEnvDescription> descriptions;
  std::vector<rl_msgs::RLStateReward> states;
  auto d = nh.subscribe<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", 1,
      [&](const rl_msgs::RLEnvDescription::ConstPtr& m) { descriptions.push_back(*m); });
  auto s = nh.subscribe<rl_msgs::RLStateReward>(
      "rl_env/rl_state_reward", 1,
      [&](const rl_msgs::RLStateReward::ConstPtr& m) { states.push_back(*m); });
  int seeds = 0;
  auto seedSub = nh.subscribe<rl_msgs::RLEnvSeedExperience>(
      "rl_env/rl_seed", 20, [&seeds](const rl_msgs::RLEnvSeedExperience::ConstPtr&) { ++seeds; });
  ros::Publisher actions = nh.advertise<rl_msgs::RLAction>("rl_agent/rl_action", 1);

  ASSERT_TRUE(spinUntil([&] { return !descriptions.empty(); }, 20.0)) << "no description";
  const auto& desc = descriptions.front();
  EXPECT_EQ(desc.num_states, 17.0f);
  EXPECT_EQ(desc.num_actions, 6.0f);
  EXPECT_EQ(desc.min_state_range.size(), 17u);
  EXPECT_EQ(desc.max_state_range[4], 3.0f);  // room id 0..3 (the original declared 2)
  EXPECT_FALSE(desc.episodic);
  EXPECT_EQ(desc.title, "Environment: LightWorld\n");

  ASSERT_TRUE(spinUntil([&] { return !states.empty(); }, 20.0)) << "no first state";
  EXPECT_EQ(states.front().state.size(), 17u);
  EXPECT_EQ(states.front().reward, 0.0f);
  EXPECT_FALSE(states.front().terminal);

  ASSERT_TRUE(spinUntil([&] { return actions.getNumSubscribers() > 0; }, 20.0));
  rl_msgs::RLAction a;
  a.action = 4;  // PICKUP
  actions.publish(a);
  ASSERT_TRUE(spinUntil([&] { return states.size() >= 2; }, 20.0)) << "no reply to an action";
  EXPECT_EQ(states.back().state.size(), 17u);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_env_smoke");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
