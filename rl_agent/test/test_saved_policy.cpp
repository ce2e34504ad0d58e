// The original's policy-file format, and savedpolicy replaying a saved Q-learning policy.
#include "rl_agent/agent/saved_policy.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/policy_file.h"
#include "rl_agent/agent/q_learner.h"
#include "small_mdps.h"

namespace {
std::string tempFile(const char* name) {
  return testing::TempDir() + "rl_agent_" + name + "_" + std::to_string(::getpid()) + ".pol";
}
}  // namespace

TEST(PolicyFile, WritesTheOriginalBinaryLayout) {
  const std::string f = tempFile("layout");
  rl_agent::PolicyFile::write(f, 2, 3, {{{1.0f, 2.0f}, {0.5f, -1.0f, 4.0f}}});
  std::ifstream in(f, std::ios::binary);
  int header[2];
  float rest[5];
  in.read(reinterpret_cast<char*>(header), sizeof header);
  in.read(reinterpret_cast<char*>(rest), sizeof rest);
  ASSERT_TRUE(in);
  EXPECT_EQ(header[0], 2);
  EXPECT_EQ(header[1], 3);
  EXPECT_FLOAT_EQ(rest[0], 1.0f);
  EXPECT_FLOAT_EQ(rest[1], 2.0f);
  EXPECT_FLOAT_EQ(rest[4], 4.0f);
  EXPECT_EQ(in.peek(), std::char_traits<char>::eof());
  const auto c = rl_agent::PolicyFile::read(f);
  EXPECT_EQ(c.numFeatures, 2);
  EXPECT_EQ(c.numActions, 3);
  ASSERT_EQ(c.q.size(), 1u);
  EXPECT_FLOAT_EQ(c.q.at({1.0f, 2.0f})[2], 4.0f);
  std::remove(f.c_str());
}

TEST(PolicyFile, RejectsMissingAndTruncatedFiles) {
  EXPECT_THROW(rl_agent::PolicyFile::read("/nonexistent/policy"), std::runtime_error);
  const std::string f = tempFile("trunc");
  {
    std::ofstream out(f, std::ios::binary);
    const int h[2] = {2, 2};
    const float part[3] = {1, 2, 3};  // state + half a Q row
    out.write(reinterpret_cast<const char*>(h), sizeof h);
    out.write(reinterpret_cast<const char*>(part), sizeof part);
  }
  EXPECT_THROW(rl_agent::PolicyFile::read(f), std::runtime_error);
  std::remove(f.c_str());
}

TEST(SavedPolicy, RoundTripsALearnedPolicy) {
  rl_agent::QLearner::Config c;
  c.numActions = 4;
  c.gamma = 0.95f;
  c.epsilon = 0.1f;
  rl_agent::QLearner learner(c, 4);
  test_mdps::TwoRoomGrid env;
  for (int e = 0; e < 300; ++e) test_mdps::runEpisode(learner, env, 500);
  const std::string f = tempFile("roundtrip");
  learner.savePolicy(f);

  rl_agent::AgentOptions o;
  o.agent = "savedpolicy";
  o.filename = f;
  auto replay = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  // Same greedy actions wherever the learner's best action is unique.
  for (const auto& s : env.reachableStates()) {
    std::vector<float> q(4);
    for (int a = 0; a < 4; ++a) q[a] = learner.q(s, a);
    const int best = int(std::max_element(q.begin(), q.end()) - q.begin());
    int ties = 0;
    for (float v : q) ties += v >= q[best] - 1e-4f;
    if (ties == 1) {
      EXPECT_EQ(replay->firstAction(s), best);
    }
  }
  // The replayed policy walks the shortest path.
  EXPECT_EQ(test_mdps::runEpisode(*replay, env, 100), 10);
  // Saving again gives the same file.
  const std::string f2 = tempFile("roundtrip2");
  replay->savePolicy(f2);
  EXPECT_EQ(rl_agent::PolicyFile::read(f2).q, rl_agent::PolicyFile::read(f).q);
  std::remove(f.c_str());
  std::remove(f2.c_str());
}

TEST(SavedPolicy, RejectsAMismatchedTask) {
  const std::string f = tempFile("mismatch");
  rl_agent::PolicyFile::write(f, 2, 3, {{{1.0f, 2.0f}, {0.0f, 0.0f, 1.0f}}});
  EXPECT_THROW(rl_agent::SavedPolicy(4, 2, f, 1), std::invalid_argument);
  EXPECT_THROW(rl_agent::SavedPolicy(3, 5, f, 1), std::invalid_argument);
  rl_agent::SavedPolicy ok(3, 2, f, 1);
  EXPECT_EQ(ok.firstAction({1.0f, 2.0f}), 2);
  EXPECT_TRUE(ok.lastActionKnown());
  ok.firstAction({9.0f, 9.0f});
  EXPECT_FALSE(ok.lastActionKnown());
  EXPECT_THROW(rl_agent::SavedPolicy(3, 2, "", 1), std::invalid_argument);
  std::remove(f.c_str());
}
