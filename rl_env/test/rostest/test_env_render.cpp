// Acts as the agent against `env --env lightworld --render`: every step's image is
// LightWorldView's drawing of the state the node published, with the action just taken; a
// viewer that subscribes later gets the current state at once; `--render` with taxi (no view)
// exits non-zero naming the environments that have one.
#include <gtest/gtest.h>
#include <rl_msgs/RLAction.h>
#include <rl_msgs/RLStateReward.h>
#include <ros/ros.h>
#include <sensor_msgs/Image.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "rl_common/ros/spin_until.h"
#include "rl_env/render/light_world_view.h"

using rl_common::spinUntil;
using rl_env::LightWorld;
using rl_env::LightWorldView;

namespace {

std::vector<std::uint8_t> expected(const std::vector<float>& state, int lastAction) {
  return LightWorldView::render(LightWorld::decode(state), lastAction).bytes();
}

}  // namespace

TEST(EnvRender, EveryImageDrawsThePublishedState) {
  ros::NodeHandle nh;
  std::vector<rl_msgs::RLStateReward> states;
  std::vector<sensor_msgs::Image> images;
  auto s = nh.subscribe<rl_msgs::RLStateReward>(
      "rl_env/rl_state_reward", 10,
      [&](const rl_msgs::RLStateReward::ConstPtr& m) { states.push_back(*m); });
  auto i = nh.subscribe<sensor_msgs::Image>(
      "rl_env/image", 10, [&](const sensor_msgs::Image::ConstPtr& m) { images.push_back(*m); });
  ros::Publisher actions = nh.advertise<rl_msgs::RLAction>("rl_agent/rl_action", 10);

  ASSERT_TRUE(spinUntil([&] { return !states.empty() && !images.empty(); }, 30.0))
      << "no first state or image";
  const sensor_msgs::Image& first = images.back();
  EXPECT_EQ(first.encoding, "rgb8");
  EXPECT_EQ(first.width, static_cast<uint32_t>(LightWorldView::kWidth));
  EXPECT_EQ(first.height, static_cast<uint32_t>(LightWorldView::kHeight));
  EXPECT_EQ(first.step, first.width * 3);
  EXPECT_EQ(first.data, expected(states.back().state, -1));

  // PICKUP and PRESS change sensors, moves the position: each image is that step's state.
  const std::array<int, 8> plan = {0, 1, 4, 5, 3, 2, 0, 4};
  for (const int a : plan) {
    const std::size_t nStates = states.size(), nImages = images.size();
    rl_msgs::RLAction msg;
    msg.action = a;
    actions.publish(msg);
    ASSERT_TRUE(spinUntil([&] { return states.size() > nStates && images.size() > nImages; }, 10.0))
        << "no state and image after action " << a;
    EXPECT_EQ(images.back().data, expected(states.back().state, a)) << "action " << a;
    EXPECT_GT(images.back().header.seq, images[nImages - 1].header.seq);
  }

  // (A viewer connecting later is sent the current image by the connect callback; roscpp
  // shares one connection per topic within a process, so this test cannot play that viewer.)
}

TEST(EnvRender, AnEnvironmentWithoutAViewIsRefused) {
  const std::string command = std::string(RL_ENV_BINARY) + " --env taxi --render 2>&1";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  ASSERT_NE(pipe, nullptr);
  std::string output;
  std::array<char, 256> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) output += buffer.data();
  const int status = pclose(pipe.release());
  EXPECT_NE(status, 0) << output;
  EXPECT_NE(output.find("--render: taxi has no rendered view; environments with one: lightworld"),
            std::string::npos)
      << output;
}

int main(int argc, char** argv) {
  testing::InitGoogleTest(&argc, argv);
  ros::init(argc, argv, "test_env_render");
  ros::NodeHandle nh;
  return RUN_ALL_TESTS();
}
