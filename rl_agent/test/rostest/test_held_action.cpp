// The agent node's first action reaches an environment that subscribes late
// (agent_held_action.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(AgentNode, HoldsItsFirstActionUntilTheEnvironmentSubscribes) {
  ros::NodeHandle nh;
  ros::Publisher desc =
      nh.advertise<rl_msgs::RLEnvDescription>("rl_env/rl_env_description", 1, /*latch=*/true);
  ros::Publisher states =
      nh.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1, /*latch=*/true);
  rl_msgs::RLEnvDescription d;
  d.num_actions = 4;
  d.num_states = 2;
  d.min_state_range = {0, 0};
  d.max_state_range = {10, 10};
  d.max_reward = 1;
  d.reward_range = 1;
  d.title = "Environment: held action test\n";
  desc.publish(d);
  rl_msgs::RLStateReward s;
  s.state = {1, 2};
  states.publish(s);
  // The agent connects, gets both latched messages and acts, with no one to hear it yet.
  ASSERT_TRUE(spinUntil([&] { return states.getNumSubscribers() > 0; }, 20.0)) << "no agent";
  ros::WallDuration(2.0).sleep();
  std::vector<int> actions;
  auto sub = nh.subscribe<rl_msgs::RLAction>(
      "rl_agent/rl_action", 10,
      [&](const rl_msgs::RLAction::ConstPtr& m) { actions.push_back(m->action); });
  ASSERT_TRUE(spinUntil([&] { return !actions.empty(); }, 10.0))
      << "the action chosen before the environment subscribed was lost";
  EXPECT_GE(actions[0], 0);
  EXPECT_LT(actions[0], 4);
  // Exactly one action for the one state: the held one is not sent twice.
  ros::WallDuration(1.0).sleep();
  ros::spinOnce();
  EXPECT_EQ(actions.size(), 1u);
  // And the agent answers the next state as usual.
  s.state = {2, 2};
  states.publish(s);
  ASSERT_TRUE(spinUntil([&] { return actions.size() == 2; }, 10.0)) << "no answer to state 2";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_held_action");
  return RUN_ALL_TESTS();
}
