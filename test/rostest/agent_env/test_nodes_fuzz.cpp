// Malformed messages replayed against a running env node and agent node (nodes_fuzz.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLEnvSeedExperience.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>
#include <rosgraph_msgs/Log.h>

#include <climits>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr std::size_t kFeatures = 17;  // LightWorld

rl_msgs::RLEnvDescription validDescription() {
  rl_msgs::RLEnvDescription d;
  d.num_actions = 6;
  d.num_states = kFeatures;
  d.min_state_range.assign(kFeatures, 0.0f);
  d.max_state_range.assign(kFeatures, 10.0f);
  d.max_reward = 10;
  d.reward_range = 10;
  d.title = "Environment: fuzz\n";
  return d;
}

/// A description with one thing wrong.
rl_msgs::RLEnvDescription description(const std::function<void(rl_msgs::RLEnvDescription&)>& f) {
  rl_msgs::RLEnvDescription d = validDescription();
  f(d);
  return d;
}

rl_msgs::RLStateReward state(std::vector<float> s, float reward = 0.0f) {
  rl_msgs::RLStateReward m;
  m.state = std::move(s);
  m.reward = reward;
  return m;
}

rl_msgs::RLEnvSeedExperience seed(std::vector<float> from, std::vector<float> to, int action,
                                  float reward) {
  rl_msgs::RLEnvSeedExperience m;
  m.from_state = std::move(from);
  m.to_state = std::move(to);
  m.action = action;
  m.reward = reward;
  return m;
}

/// Warnings (and worse) saying "dropping" on /rosout, per node.
struct DropLines {
  long agent = 0, env = 0;
  std::vector<std::string> agentLines;
};

}  // namespace

TEST(NodesFuzz, MalformedMessagesAreLoggedOnceAndDropped) {
  ros::NodeHandle nh;
  DropLines drops;
  auto rosout = nh.subscribe<rosgraph_msgs::Log>(
      "/rosout", 10000, [&](const rosgraph_msgs::Log::ConstPtr& m) {
        if (m->level < rosgraph_msgs::Log::WARN || m->msg.find("dropping") != 0) return;
        if (m->name == "/agent") {
          ++drops.agent;
          drops.agentLines.push_back(m->msg);
        } else if (m->name == "/env") {
          ++drops.env;
        }
      });
  long actions = 0;
  auto actionSub = nh.subscribe<rl_msgs::RLAction>(
      "rl_agent/rl_action", 1000, [&](const rl_msgs::RLAction::ConstPtr&) { ++actions; });
  ASSERT_TRUE(spinUntil([&] { return actions >= 20; }, 30.0)) << "the pair does not step";

  ros::Publisher descPub = nh.advertise<rl_msgs::RLEnvDescription>("rl_env/rl_env_description", 10);
  ros::Publisher statePub = nh.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 1000);
  ros::Publisher seedPub = nh.advertise<rl_msgs::RLEnvSeedExperience>("rl_env/rl_seed", 10);
  ros::Publisher actionPub = nh.advertise<rl_msgs::RLAction>("rl_agent/rl_action", 10);
  ASSERT_TRUE(spinUntil(
      [&] {
        return descPub.getNumSubscribers() > 0 && statePub.getNumSubscribers() > 0 &&
               seedPub.getNumSubscribers() > 0 && actionPub.getNumSubscribers() > 0;
      },
      10.0));
  ros::WallDuration(0.5).sleep();

  const std::vector<rl_msgs::RLEnvDescription> descriptions = {
      description([](auto& d) { d.num_actions = 0; }),
      description([](auto& d) { d.num_actions = -1; }),
      description([](auto& d) { d.num_actions = kNaN; }),
      description([](auto& d) { d.num_actions = 1e9f; }),
      description([](auto& d) { d.num_actions = 3e9f; }),
      description([](auto& d) { d.num_actions = kInf; }),
      description([](auto& d) { d.num_states = 16.5f; }),
      description([](auto& d) { d.max_state_range.pop_back(); }),
      description([](auto& d) { d.min_state_range[3] = 11.0f; }),
      description([](auto& d) { d.reward_range = -1.0f; }),
      description([](auto& d) { d.max_reward = kNaN; }),
      description([](auto& d) { d.max_state_range[0] = kInf; }),
  };
  const std::vector<float> ok(kFeatures, 1.0f);
  std::vector<float> nan = ok, inf = ok, negInf = ok;
  nan[4] = kNaN;
  inf[0] = kInf;
  negInf[16] = -kInf;
  const std::vector<rl_msgs::RLStateReward> states = {
      state({}),
      state(std::vector<float>(kFeatures + 1, 1.0f)),
      state(std::vector<float>(1000, 1.0f)),
      state(nan),
      state(inf),
      state(negInf),
      state(ok, kNaN),
      state(ok, kInf),
      state(ok, -kInf)};
  const std::vector<rl_msgs::RLEnvSeedExperience> seeds = {
      seed({1.0f}, ok, 0, 0.0f), seed(ok, nan, 0, 0.0f), seed(ok, ok, -1, 0.0f),
      seed(ok, ok, 99, 0.0f), seed(ok, ok, 0, kNaN)};
  const std::vector<int> badActions = {-1, 6, 1000000, INT_MIN, INT_MAX};

  // One message at a time, below the log's rate limit: one line each.
  const auto pause = [] {
    ros::spinOnce();
    ros::WallDuration(0.15).sleep();
  };
  for (const auto& d : descriptions) descPub.publish(d), pause();
  for (const auto& s : states) statePub.publish(s), pause();
  for (const auto& s : seeds) seedPub.publish(s), pause();
  for (int a : badActions) {
    rl_msgs::RLAction m;
    m.action = a;
    actionPub.publish(m);
    pause();
  }
  const long toAgent = static_cast<long>(descriptions.size() + states.size() + seeds.size());
  const long toEnv = static_cast<long>(badActions.size());
  spinUntil([&] { return drops.agent >= toAgent && drops.env >= toEnv; }, 10.0);
  ros::WallDuration(0.5).sleep();
  ros::spinOnce();
  std::string seen;
  for (const auto& l : drops.agentLines) seen += l + "\n";
  EXPECT_EQ(drops.agent, toAgent) << seen;
  EXPECT_EQ(drops.env, toEnv);

  // The pair keeps stepping, and the agent still answers the env's states.
  long before = actions;
  EXPECT_TRUE(spinUntil([&] { return actions >= before + 50; }, 30.0))
      << "stopped after the replay";

  // A burst: 50 malformed states within 0.3 s (spaced so that the agent's state queue of 10
  // loses none), then 500 at once. The log counts them instead of writing a line each.
  ros::WallDuration(1.1).sleep();  // a fresh rate window
  const long burstStart = drops.agent;
  for (int i = 0; i < 50; ++i) {
    statePub.publish(state(nan));
    ros::WallDuration(0.005).sleep();
  }
  for (int i = 0; i < 500; ++i) statePub.publish(state(nan));
  ros::WallDuration(1.5).sleep();
  statePub.publish(state({}));  // a new window: this line names the held-back ones
  spinUntil([&] { return drops.agent > burstStart + 10; }, 5.0);
  ros::WallDuration(0.5).sleep();
  ros::spinOnce();
  EXPECT_LE(drops.agent - burstStart, 12) << "a burst of 550 flooded the log";
  EXPECT_GE(drops.agent - burstStart, 2);
  bool counted = false;
  for (std::size_t i = static_cast<std::size_t>(burstStart); i < drops.agentLines.size(); ++i) {
    counted |= drops.agentLines[i].find("similar lines held back") != std::string::npos;
  }
  EXPECT_TRUE(counted) << "no line says how many were held back";
  before = actions;
  EXPECT_TRUE(spinUntil([&] { return actions >= before + 50; }, 30.0)) << "stopped after the burst";
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_nodes_fuzz");
  return RUN_ALL_TESTS();
}
