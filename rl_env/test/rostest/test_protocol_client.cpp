// A client of the rl_msgs protocol that takes no seed experiences (protocol_client.test): the
// env node sends it the first state and answers its actions.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(ProtocolClient, GetsStatesWithoutSubscribingToSeeds) {
  ros::NodeHandle nh;
  rl_msgs::RLEnvDescription desc;
  bool described = false;
  std::vector<rl_msgs::RLStateReward> states;
  auto d = nh.subscribe<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", 1, [&](const rl_msgs::RLEnvDescription::ConstPtr& m) {
        desc = *m;
        described = true;
      });
  auto s = nh.subscribe<rl_msgs::RLStateReward>(
      "rl_env/rl_state_reward", 10,
      [&](const rl_msgs::RLStateReward::ConstPtr& m) { states.push_back(*m); });
  ros::Publisher actions = nh.advertise<rl_msgs::RLAction>("rl_agent/rl_action", 10);
  ASSERT_TRUE(spinUntil([&] { return described && !states.empty(); }, 20.0))
      << "no first state for a client without a seed subscription";
  EXPECT_EQ(states[0].state.size(), static_cast<std::size_t>(desc.num_states));
  EXPECT_EQ(states[0].reward, 0.0f);
  rl_msgs::RLAction a;
  for (int i = 0; i < 3; ++i) {
    const std::size_t before = states.size();
    a.action = i;
    actions.publish(a);
    ASSERT_TRUE(spinUntil([&] { return states.size() > before; }, 10.0)) << "no reply, step " << i;
    EXPECT_EQ(states.back().state.size(), static_cast<std::size_t>(desc.num_states));
  }
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_protocol_client");
  return RUN_ALL_TESTS();
}
