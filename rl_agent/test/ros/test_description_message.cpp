// The agent node's reading of rl_msgs/RLEnvDescription (fromMessage): a description an agent
// can be built from is converted; one that would crash or exhaust the node is refused with a
// message that names the field (issue 15's fuzzing: num_actions 1e9, +inf, 3e9, num_states
// 16.5, min above max, +-FLT_MAX ranges, a negative reward_range).
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

#include "rl_agent/ros/agent_node.h"

namespace {

rl_msgs::RLEnvDescription lightWorldLike() {
  rl_msgs::RLEnvDescription m;
  m.num_actions = 6;
  m.num_states = 3;
  m.min_state_range = {0, 0, 0};
  m.max_state_range = {10, 10, 1};
  m.max_reward = 10;
  m.reward_range = 10;
  m.episodic = false;
  m.stochastic = true;
  m.title = "Environment: test\n";
  return m;
}

/// The message fromMessage refuses `m` with, or "" if it accepts it.
std::string refusal(const rl_msgs::RLEnvDescription& m) {
  try {
    rl_agent::fromMessage(m);
    return "";
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
}

TEST(DescriptionMessage, AConsistentDescriptionIsConverted) {
  const auto d = rl_agent::fromMessage(lightWorldLike());
  EXPECT_EQ(d.numActions, 6);
  EXPECT_EQ(d.numFeatures(), 3u);
  EXPECT_EQ(d.maxReward, 10.0f);
  EXPECT_EQ(d.minReward, 0.0f);
  auto m = lightWorldLike();
  m.min_state_range[2] = m.max_state_range[2] = 1.0f;  // a constant feature is allowed
  m.reward_range = 0.0f;                               // so is a constant reward
  EXPECT_EQ(refusal(m), "");
  m.num_actions = 65536.0f;
  EXPECT_EQ(refusal(m), "");
}

TEST(DescriptionMessage, ActionCountsThatCannotBeBuiltAreRefusedByName) {
  for (float bad : {0.0f, -1.0f, 2.5f, 1e9f, 3e9f, 65537.0f, INFINITY, -INFINITY, NAN}) {
    auto m = lightWorldLike();
    m.num_actions = bad;
    EXPECT_NE(refusal(m).find("num_actions must be a whole number in [1, 65536]"),
              std::string::npos)
        << bad << ": " << refusal(m);
  }
}

TEST(DescriptionMessage, FeatureCountsAndRangesAreChecked) {
  auto m = lightWorldLike();
  m.num_states = 16.5f;
  EXPECT_NE(refusal(m).find("num_states must be a whole number"), std::string::npos);
  m = lightWorldLike();
  m.num_states = 4;  // three ranges
  EXPECT_NE(refusal(m).find("does not match the range lengths"), std::string::npos);
  m = lightWorldLike();
  m.min_state_range[1] = 11.0f;
  EXPECT_NE(refusal(m).find("feature 1: min_state_range"), std::string::npos) << refusal(m);
  m = lightWorldLike();
  m.min_state_range[0] = -FLT_MAX;
  m.max_state_range[0] = FLT_MAX;
  EXPECT_NE(refusal(m).find("feature 0: the range's span overflows"), std::string::npos);
  m = lightWorldLike();
  m.max_state_range[2] = NAN;
  EXPECT_NE(refusal(m).find("must be finite"), std::string::npos);
  m = lightWorldLike();
  m.reward_range = -1.0f;
  EXPECT_NE(refusal(m).find("reward_range must be >= 0"), std::string::npos);
}

}  // namespace
