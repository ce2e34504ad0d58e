// Sim + bridge + agent through ROS (rostest/nao_arm.test): the bridge describes the paper's
// task (8 features, 5 actions), its states have 8 in-range features, the agent's actions move
// the shoulder joints by 8 degrees, the bridge commands the simulated driver on /joint_angles,
// and the pink pixel count changes as the arm moves.
#include <gtest/gtest.h>
#include <naoqi_bridge_msgs/JointAnglesWithSpeed.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <cmath>
#include <map>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace {

struct Recorder {
  std::mutex mutex;
  rl_msgs::RLEnvDescription::ConstPtr description;
  std::vector<std::vector<float>> states;
  std::vector<float> rewards;
  // Each action with the number of states seen when it arrived: the action topic is not
  // latched, so the first actions can go by before this node connects; the arrival positions
  // tell how many (see the pairing below).
  std::vector<std::pair<int, std::size_t>> actions;
  int commands = 0;
  bool commandNamesOk = true;
};

}  // namespace

TEST(NaoArm, AgentMovesTheSimulatedArmThroughTheBridge) {
  ros::NodeHandle nh;
  Recorder rec;
  auto d = nh.subscribe<rl_msgs::RLEnvDescription>(
      "rl_env/rl_env_description", 1, [&](const rl_msgs::RLEnvDescription::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(rec.mutex);
        rec.description = m;
      });
  auto s = nh.subscribe<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 100,
                                                [&](const rl_msgs::RLStateReward::ConstPtr& m) {
                                                  std::lock_guard<std::mutex> lock(rec.mutex);
                                                  rec.states.push_back(m->state);
                                                  rec.rewards.push_back(m->reward);
                                                });
  auto a = nh.subscribe<rl_msgs::RLAction>("rl_agent/rl_action", 100,
                                           [&](const rl_msgs::RLAction::ConstPtr& m) {
                                             std::lock_guard<std::mutex> lock(rec.mutex);
                                             rec.actions.emplace_back(m->action, rec.states.size());
                                           });
  auto c = nh.subscribe<naoqi_bridge_msgs::JointAnglesWithSpeed>(
      "joint_angles", 100, [&](const naoqi_bridge_msgs::JointAnglesWithSpeed::ConstPtr& m) {
        std::lock_guard<std::mutex> lock(rec.mutex);
        ++rec.commands;
        rec.commandNamesOk = rec.commandNamesOk && m->joint_names.size() == 2 &&
                             m->joint_names[0] == "RShoulderPitch" &&
                             m->joint_names[1] == "RShoulderRoll" && m->relative == 0;
      });
  ros::AsyncSpinner spinner(1);
  spinner.start();
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(45.0);
  while (ros::ok() && ros::WallTime::now() < deadline) {
    {
      std::lock_guard<std::mutex> lock(rec.mutex);
      if (rec.states.size() >= 16 && rec.actions.size() >= 15) break;
    }
    ros::WallDuration(0.05).sleep();
  }
  spinner.stop();
  std::lock_guard<std::mutex> lock(rec.mutex);
  ASSERT_TRUE(rec.description);
  EXPECT_EQ(rec.description->num_states, 8.0f);
  EXPECT_EQ(rec.description->num_actions, 5.0f);
  EXPECT_FALSE(rec.description->episodic);
  ASSERT_GE(rec.states.size(), 16u) << "the bridge stopped publishing states";
  ASSERT_GE(rec.actions.size(), 15u);
  EXPECT_GE(rec.commands, 15);
  EXPECT_TRUE(rec.commandNamesOk);
  for (const auto& st : rec.states) {
    ASSERT_EQ(st.size(), 8u);
    for (std::size_t f = 0; f < 8; ++f) {
      EXPECT_GE(st[f], rec.description->min_state_range[f]) << "feature " << f;
      EXPECT_LE(st[f], rec.description->max_state_range[f]) << "feature " << f;
    }
  }
  // The first state has no reward; after it the pink task rewards the pink count.
  EXPECT_EQ(rec.rewards[0], 0.0f);
  for (std::size_t k = 1; k < rec.states.size(); ++k) {
    EXPECT_EQ(rec.rewards[k], rec.states[k][5]) << "state " << k;
  }
  // Which state each action answered. The agent answers every state with one action, so the
  // k-th action received answers state k + offset, where offset counts the first actions that
  // went by before this node connected. Arrival order across the two topics is not guaranteed
  // (a loaded machine can deliver state j+1 before the action that caused it), so the offset
  // is the most common arrival position and the pairing is by count.
  std::map<long, int> offsets;
  for (std::size_t k = 0; k < rec.actions.size(); ++k) {
    ++offsets[static_cast<long>(rec.actions[k].second) - 1 - static_cast<long>(k)];
  }
  long offset = 0;
  int agreeing = 0;
  for (const auto& [o, count] : offsets) {
    if (count > agreeing) {
      offset = o;
      agreeing = count;
    }
  }
  // One action per state: most actions arrive right after the state they answer, and no more
  // actions than states arrived (two actions for one state would shift every later one).
  EXPECT_GE(agreeing * 5, static_cast<int>(rec.actions.size()) * 4)
      << "actions do not follow their states one to one";
  EXPECT_LE(rec.actions.size(), rec.states.size() + 1) << "more actions than states";
  // The state after an action follows it. Moves change their joint by about 8 degrees.
  int moves = 0, wholeMoves = 0, pinkChanges = 0;
  std::string partial;
  std::set<float> pink;
  for (std::size_t k = 0; k < rec.actions.size(); ++k) {
    const int act = rec.actions[k].first;
    const long answered = static_cast<long>(k) + offset;
    if (answered < 0 || answered + 1 >= static_cast<long>(rec.states.size())) continue;
    const auto& s0 = rec.states[answered];
    const auto& s1 = rec.states[answered + 1];
    pink.insert(s1[5]);
    const float dp = s1[0] - s0[0], dr = s1[1] - s0[1];
    if (act == 4) {
      EXPECT_NEAR(dp, 0.0f, 1.5f) << "step " << k;
      EXPECT_NEAR(dr, 0.0f, 1.5f) << "step " << k;
      continue;
    }
    const float expected = (act == 0 || act == 2) ? 8.0f : -8.0f;
    const float moved = act < 2 ? dp : dr;
    const float atLimit = act < 2 ? std::abs(s0[0]) > 110.0f : (s0[1] < -70.0f || s0[1] > 12.0f);
    if (!atLimit) {
      // A loaded machine can deliver a joint state from before the arm arrived; the next step
      // then catches up. Most moves must be whole.
      if (std::abs(moved - expected) <= 2.0f) {
        ++wholeMoves;
      } else {
        partial += "step " + std::to_string(k) + " action " + std::to_string(act) + " moved " +
                   std::to_string(moved) + "; ";
      }
      ++moves;
      if (std::abs(s1[5] - s0[5]) > 50.0f) ++pinkChanges;
    }
  }
  EXPECT_GE(moves, 5);
  EXPECT_GE(wholeMoves * 5, moves * 4) << "moves not of 8 +- 2 degrees: " << partial;
  EXPECT_GE(pinkChanges, 1) << "the pink count never changed as the arm moved";
  EXPECT_GT(*pink.rbegin(), 0.0f) << "the pink square was never seen";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_nao_arm");
  return RUN_ALL_TESTS();
}
