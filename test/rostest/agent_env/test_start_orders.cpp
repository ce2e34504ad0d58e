// The agent and env nodes in every start order, the env restarted mid-run, and an environment
// that sends no seeds (agent_start_orders.test).
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLEnvDescription.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "child_process.h"
#include "rl_common/ros/spin_until.h"

using rl_common::spinUntil;

namespace {

const std::string kLogs = "/tmp/rl_start_orders_" + std::to_string(::getpid());

pid_t startAgent(const std::string& log) {
  return test_nodes::start({AGENT_BIN, "__name:=agent", "--agent", "qlearner", "--seed", "3"},
                           kLogs + "/" + log);
}

pid_t startEnv(const std::string& log) {
  return test_nodes::start(
      {"rosrun", "rl_env", "env", "__name:=env", "--env", "taxi", "--seed", "4"},
      kLogs + "/" + log);
}

/// Counts the agent's actions.
struct Actions {
  long count = 0;
  ros::Subscriber sub;
  explicit Actions(ros::NodeHandle& nh)
      : sub(nh.subscribe<rl_msgs::RLAction>(
            "rl_agent/rl_action", 1000, [this](const rl_msgs::RLAction::ConstPtr&) { ++count; })) {}
  /// True once `more` actions beyond the count now have been seen (within `seconds`).
  bool grows(long more, double seconds) {
    const long target = count + more;
    return spinUntil([&] { return count >= target; }, seconds);
  }
};

std::string logs(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& n : names) text += "--- " + n + "\n" + test_nodes::fileText(kLogs + "/" + n);
  return text;
}

}  // namespace

TEST(StartOrders, AgentFirstEnvFirstAndTheEnvRestartedMidRun) {
  ASSERT_EQ(std::system(("mkdir -p " + kLogs).c_str()), 0);
  ros::NodeHandle nh;
  Actions actions(nh);

  // The agent waits for an environment that comes 2 s later.
  const pid_t agent = startAgent("agent1.log");
  ros::WallDuration(2.0).sleep();
  pid_t env = startEnv("env1.log");
  EXPECT_TRUE(actions.grows(200, 30.0)) << "agent first: " << actions.count << " actions\n"
                                        << logs({"agent1.log", "env1.log"});

  // The env dies mid-run (SIGKILL: no clean shutdown) and is started again.
  test_nodes::stop(env, SIGKILL);
  ros::WallDuration(1.0).sleep();
  env = startEnv("env2.log");
  EXPECT_TRUE(actions.grows(200, 30.0)) << "env restarted: " << actions.count << " actions\n"
                                        << logs({"agent1.log", "env2.log"});
  test_nodes::stop(agent, SIGINT);

  // The env already runs (its state latched) when the agent starts.
  ros::WallDuration(1.0).sleep();
  const pid_t agent2 = startAgent("agent2.log");
  EXPECT_TRUE(actions.grows(200, 30.0)) << "env first: " << actions.count << " actions\n"
                                        << logs({"agent2.log", "env2.log"});
  test_nodes::stop(agent2, SIGINT);
  test_nodes::stop(env, SIGINT);
}

TEST(StartOrders, AnEnvironmentThatSendsNoSeeds) {
  // This node is the environment: a description and states, never a seed, never a seed topic.
  ros::NodeHandle nh;
  ros::Publisher desc =
      nh.advertise<rl_msgs::RLEnvDescription>("rl_env/rl_env_description", 1, /*latch=*/true);
  ros::Publisher states =
      nh.advertise<rl_msgs::RLStateReward>("rl_env/rl_state_reward", 10, /*latch=*/true);
  rl_msgs::RLEnvDescription d;
  d.num_actions = 2;
  d.num_states = 1;
  d.min_state_range = {0};
  d.max_state_range = {9};
  d.max_reward = 1;
  d.reward_range = 1;
  d.episodic = false;
  d.title = "Environment: seedless walk\n";
  desc.publish(d);
  float x = 0;
  long answered = 0;
  auto sub = nh.subscribe<rl_msgs::RLAction>(
      "rl_agent/rl_action", 100, [&](const rl_msgs::RLAction::ConstPtr& m) {
        x = std::max(0.0f, std::min(9.0f, x + (m->action == 1 ? 1.0f : -1.0f)));
        rl_msgs::RLStateReward s;
        s.state = {x};
        s.reward = x == 9.0f ? 1.0f : 0.0f;
        states.publish(s);
        ++answered;
      });
  rl_msgs::RLStateReward s;
  s.state = {x};
  states.publish(s);
  const pid_t agent = startAgent("agent3.log");
  EXPECT_TRUE(spinUntil([&] { return answered >= 100; }, 30.0)) << answered << " actions\n"
                                                                << logs({"agent3.log"});
  test_nodes::stop(agent, SIGINT);
  std::system(("rm -rf " + kLogs).c_str());
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_start_orders");
  return RUN_ALL_TESTS();
}
