// The agent node's first action, and its episode-end message, reach an environment that
// subscribes late, even when an observer heard them first (agent_held_action.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <string>
#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

namespace {

// Subscribers of `topic` known to the master (the observer's subscriptions).
int subscriberCount(const std::string& topic) {
  XmlRpc::XmlRpcValue request, response, payload;
  request[0] = ros::this_node::getName();
  if (!ros::master::execute("getSystemState", request, response, payload, false)) return 0;
  const XmlRpc::XmlRpcValue& subscribers = payload[1];
  for (int i = 0; i < subscribers.size(); ++i) {
    if (static_cast<std::string>(subscribers[i][0]) == topic) {
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
  ASSERT_TRUE(spinUntil(
      [&] {
        return subscriberCount("/rl_agent/rl_action") > 0 &&
               subscriberCount("/rl_agent/rl_experiment_info") > 0;
      },
      20.0))
      << "no observer";
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

  // The episode ends while this node (the env) does not listen to rl_experiment_info yet, only
  // the observer does: the env resets on that message, so the agent holds it for the state's
  // sender too (before, it was lost, and an agent restarted beside a running env stalled).
  s.state = {3, 2};
  s.terminal = true;
  states.publish(s);
  ros::WallDuration(2.0).sleep();
  std::vector<rl_msgs::RLExperimentInfo> infos;
  auto infoSub = nh.subscribe<rl_msgs::RLExperimentInfo>(
      "rl_agent/rl_experiment_info", 10,
      [&](const rl_msgs::RLExperimentInfo::ConstPtr& m) { infos.push_back(*m); });
  ASSERT_TRUE(spinUntil([&] { return !infos.empty(); }, 10.0))
      << "the episode end published before the environment subscribed was lost";
  EXPECT_EQ(infos[0].episode_number, 0);
  EXPECT_EQ(infos[0].number_actions, 2);
  ros::WallDuration(1.0).sleep();
  ros::spinOnce();
  EXPECT_EQ(infos.size(), 1u) << "the held episode end was sent twice";
  EXPECT_EQ(actions.size(), 2u) << "the agent acted on a terminal state";
}

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "--observe") {
    // The observer: listens to the agent's actions and episode ends and does nothing else.
    ros::init(argc, argv, "observer");
    ros::NodeHandle nh;
    auto sub =
        nh.subscribe<rl_msgs::RLAction>("rl_agent/rl_action", 10,
                                        boost::function<void(const rl_msgs::RLAction::ConstPtr&)>(
                                            [](const rl_msgs::RLAction::ConstPtr&) {}));
    auto infoSub = nh.subscribe<rl_msgs::RLExperimentInfo>(
        "rl_agent/rl_experiment_info", 10,
        boost::function<void(const rl_msgs::RLExperimentInfo::ConstPtr&)>(
            [](const rl_msgs::RLExperimentInfo::ConstPtr&) {}));
    ros::spin();
    return 0;
  }
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_held_action");
  return RUN_ALL_TESTS();
}
