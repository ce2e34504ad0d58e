// Acts as the agent against the env node (TwoRooms): the original handshake order, then steps,
// an episode reset through RLExperimentInfo, the new reset service and malformed actions.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLStateReward.h>
#include <rl_msgs/Reset.h>
#include <ros/ros.h>

#include <algorithm>
#include <string>
#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(EnvNode, HandshakeStepsResetsAndBadActions) {
  ros::NodeHandle nh;
  std::vector<std::string> order;  // "D", "S" (seed), "X" (state)
  rl_msgs::RLEnvDescription desc;
  std::vector<rl_msgs::RLStateReward> states;
  auto d = nh.subscribe<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", 1, [&](const rl_msgs::RLEnvDescription::ConstPtr& m) {
        desc = *m;
        order.push_back("D");
      });
  auto seeds = nh.subscribe<rl_msgs::RLEnvSeedExperience>(
      "rl_env/rl_seed", 20, [&](const rl_msgs::RLEnvSeedExperience::ConstPtr& m) {
        EXPECT_EQ(m->from_state.size(), 2u);
        EXPECT_EQ(m->to_state.size(), 2u);
        order.push_back("S");
      });
  auto s = nh.subscribe<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 10,
                                                [&](const rl_msgs::RLStateReward::ConstPtr& m) {
                                                  states.push_back(*m);
                                                  order.push_back("X");
                                                });
  ros::Publisher actions = nh.advertise<rl_msgs::RLAction>("rl_agent/rl_action", 10);
  ros::Publisher info = nh.advertise<rl_msgs::RLExperimentInfo>("rl_agent/rl_experiment_info", 1);

  ASSERT_TRUE(spinUntil([&] { return !states.empty(); }, 30.0)) << "no first state";
  // The description and both seeds, then the first state (reward 0, not terminal). ROS does
  // not order messages across topics: the description (latched) and the seeds both go out as
  // their connections come up, in either order, which is why the agent node keeps seeds that
  // come before the description. The state waits for both.
  ASSERT_EQ(order.size(), 4u);
  EXPECT_EQ(std::count(order.begin(), order.begin() + 3, "D"), 1);
  EXPECT_EQ(std::count(order.begin(), order.begin() + 3, "S"), 2);
  EXPECT_EQ(order[3], "X");
  EXPECT_EQ(desc.num_states, 2.0f);
  EXPECT_EQ(desc.num_actions, 4.0f);
  EXPECT_TRUE(desc.episodic);
  EXPECT_EQ(states[0].state.size(), static_cast<std::size_t>(desc.num_states));
  EXPECT_EQ(states[0].reward, 0.0f);
  EXPECT_FALSE(states[0].terminal);

  ASSERT_TRUE(spinUntil([&] { return actions.getNumSubscribers() > 0; }, 10.0));
  rl_msgs::RLAction a;
  for (int i = 0; i < 5; ++i) {
    const std::size_t before = states.size();
    a.action = i % 4;
    actions.publish(a);
    ASSERT_TRUE(spinUntil([&] { return states.size() > before; }, 10.0)) << "no reply, step " << i;
    EXPECT_EQ(states.back().state.size(), 2u);
    EXPECT_TRUE(states.back().reward == -1.0f || states.back().reward == 0.0f);
  }

  // Malformed actions are dropped (no reply) and the node keeps serving.
  const std::size_t before = states.size();
  a.action = 4;
  actions.publish(a);
  a.action = -1;
  actions.publish(a);
  ros::WallDuration(0.5).sleep();
  ros::spinOnce();
  EXPECT_EQ(states.size(), before);
  a.action = 0;
  actions.publish(a);
  ASSERT_TRUE(spinUntil([&] { return states.size() > before; }, 10.0)) << "node stopped serving";

  // An episode report resets the environment: a start state with reward 0 follows.
  ASSERT_TRUE(spinUntil([&] { return info.getNumSubscribers() > 0; }, 10.0));
  const std::size_t beforeInfo = states.size();
  rl_msgs::RLExperimentInfo e;
  e.episode_number = 0;
  info.publish(e);
  ASSERT_TRUE(spinUntil([&] { return states.size() > beforeInfo; }, 10.0));
  EXPECT_EQ(states.back().reward, 0.0f);
  EXPECT_GE(states.back().state[1], 6.0f);  // TwoRooms starts in the right room

  // The reset service reseeds: two resets with the same seed give the same start state.
  ASSERT_TRUE(ros::service::waitForService("rl_env/reset", 10000));
  rl_msgs::Reset srv;
  srv.request.use_seed = true;
  srv.request.seed = 77;
  ASSERT_TRUE(ros::service::call("rl_env/reset", srv));
  EXPECT_TRUE(srv.response.success);
  ASSERT_TRUE(spinUntil([&] { return states.size() > beforeInfo + 1; }, 10.0));
  const auto first = states.back().state;
  ASSERT_TRUE(ros::service::call("rl_env/reset", srv));
  ASSERT_TRUE(spinUntil([&] { return states.size() > beforeInfo + 2; }, 10.0));
  EXPECT_EQ(states.back().state, first);
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_env_node");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
