// Watches an agent node and an env node talk over the original protocol, then feeds the agent
// malformed messages and checks that it keeps acting.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLExperimentInfo.h>
#include <rl_msgs/RLRewardBreakdown.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <limits>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

TEST(AgentEnv, EpisodesCompleteAndBadMessagesAreDropped) {
  ros::NodeHandle nh;
  int numActions = 6;
  ros::NodeHandle("~").param("num_actions", numActions, numActions);
  int actions = 0, infos = 0, breakdowns = 0;
  int lastEpisode = -1;
  auto a = nh.subscribe<rl_msgs::RLAction>("rl_agent/rl_action", 100,
                                           [&](const rl_msgs::RLAction::ConstPtr& m) {
                                             EXPECT_GE(m->action, 0);
                                             EXPECT_LT(m->action, numActions);
                                             ++actions;
                                           });
  auto i = nh.subscribe<rl_msgs::RLExperimentInfo>(
      "rl_agent/rl_experiment_info", 100, [&](const rl_msgs::RLExperimentInfo::ConstPtr& m) {
        EXPECT_EQ(m->episode_number, lastEpisode + 1);
        EXPECT_GT(m->number_actions, 0);
        lastEpisode = m->episode_number;
        ++infos;
      });
  std::size_t numFeatures = 0;
  auto d = nh.subscribe<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", 1, [&](const rl_msgs::RLEnvDescription::ConstPtr& m) {
        numFeatures = static_cast<std::size_t>(m->num_states);
      });
  auto b = nh.subscribe<rl_msgs::RLRewardBreakdown>(
      "rl_agent/rl_reward_breakdown", 100,
      [&](const rl_msgs::RLRewardBreakdown::ConstPtr&) { ++breakdowns; });

  ASSERT_TRUE(spinUntil([&] { return infos >= 2; }, 90.0))
      << "episodes did not complete: " << actions << " actions, " << infos << " episodes";
  EXPECT_GT(actions, 10);
  EXPECT_GT(breakdowns, 10);

  // Malformed states, published as if by the environment: dropped, the agent keeps going.
  ros::Publisher bad = nh.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1);
  ASSERT_TRUE(spinUntil([&] { return bad.getNumSubscribers() > 0; }, 10.0));
  ASSERT_GT(numFeatures, 0u) << "no environment description";
  rl_msgs::RLStateReward wrongLength;  // one feature too many for this environment
  wrongLength.state.assign(numFeatures + 1, 1.0f);
  bad.publish(wrongLength);
  rl_msgs::RLStateReward nan;  // the right length, one value NaN
  nan.state.assign(numFeatures, 0.0f);
  nan.state.back() = std::numeric_limits<float>::quiet_NaN();
  bad.publish(nan);
  const int before = actions;
  ASSERT_TRUE(spinUntil([&] { return actions > before + 20; }, 30.0)) << "agent stopped acting";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_agent_env");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
