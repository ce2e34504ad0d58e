// The agent node's first action reaches an environment that subscribes late, even when an
// observer heard it first (agent_held_action.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <string>
#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

namespace {

// Subscribers of rl_agent/rl_action known to the master (the observer's subscription).
int actionSubscriberCount() {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false)) return 0;
  const XmlRpc::XmlRpcValue& subscribers = payload[1];
  for (int i = 0; i < subscribers.size(); ++i) {
    if (static_cast<std::string>(subscribers[i][0]) == "/rl_agent/rl_action") {
      return subscribers[i][1].size();
    }
  }
  return 0;
}

}  // namespace

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
  // An observer (this binary run as the node `observer`, like rosbag record) hears the agent's
  // actions before the environment does: the agent must still hold its action for the node
  // whose state it answers (before, one listener was enough to send it, and the env lost it).
  ASSERT_TRUE(spinUntil([&] { return actionSubscriberCount() > 0; }, 20.0)) << "no observer";
  ASSERT_TRUE(spinUntil([&] { return states.getNumSubscribers() > 0; }, 20.0)) << "no agent";
  ros::WallDuration(1.0).sleep();  // the agent's connection callback for the observer has run
  rl_msgs::RLStateReward s;
  s.state = {1, 2};
  states.publish(s);
  // The agent gets the state and acts, with only the observer to hear it.
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
  if (argc > 1 && std::string(argv[1]) == "--observe") {
    // The observer: listens to the agent's actions and does nothing else.
    ros::init(argc, argv, "observer");
    ros::NodeHandle nh;
    auto sub =
        nh.subscribe<rl_msgs::RLAction>("rl_agent/rl_action", 10,
                                        boost::function<void(const rl_msgs::RLAction::ConstPtr&)>(
                                            [](const rl_msgs::RLAction::ConstPtr&) {}));
    ros::spin();
    return 0;
  }
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_held_action");
  return RUN_ALL_TESTS();
}
