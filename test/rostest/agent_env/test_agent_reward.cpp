// Watches an agent node act against an env node and adds up the rewards the environment
// returns: the agent must earn at least ~min_reward within ~max_actions actions (e.g. the
// optimal agent leaving LightWorld rooms, +10 each, where random actions rarely leave one).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(AgentReward, EarnsTheRewardWithinTheActions) {
  ros::NodeHandle nh;
  ros::NodeHandle pnh("~");
  double minReward = 30.0;
  int maxActions = 300;
  int numActions = 6;
  pnh.param("min_reward", minReward, minReward);
  pnh.param("max_actions", maxActions, maxActions);
  pnh.param("num_actions", numActions, numActions);
  int actions = 0;
  double reward = 0.0;
  int actionsAtGoal = -1;
  auto a = nh.subscribe<rl_msgs::RLAction>("rl_agent/rl_action", 1000,
                                           [&](const rl_msgs::RLAction::ConstPtr& m) {
                                             EXPECT_GE(m->action, 0);
                                             EXPECT_LT(m->action, numActions);
                                             ++actions;
                                           });
  auto s = nh.subscribe<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1000,
                                                [&](const rl_msgs::RLStateReward::ConstPtr& m) {
                                                  reward += m->reward;
                                                  if (actionsAtGoal < 0 && reward >= minReward)
                                                    actionsAtGoal = actions;
                                                });
  ASSERT_TRUE(spinUntil([&] { return actionsAtGoal >= 0; }, 60.0))
      << "earned " << reward << " in " << actions << " actions; expected " << minReward;
  // The listener may have joined a few actions late: the count is a lower bound.
  EXPECT_LE(actionsAtGoal, maxActions)
      << "earned " << minReward << " but only after " << actionsAtGoal << " actions";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_agent_reward");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
