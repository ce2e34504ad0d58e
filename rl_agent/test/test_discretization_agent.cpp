#include "rl_agent/agent/discretization_agent.h"

#include <gtest/gtest.h>

#include "rl_agent/agent/agent_registry.h"

using rl_common::State;

namespace {
/// Records the states it is given.
class Recorder : public rl_common::Agent {
 public:
  std::vector<State> seen;
  std::vector<rl_common::Experience> seeds;
  int firstAction(const State& s) override {
    seen.push_back(s);
    return 0;
  }
  int nextAction(float, const State& s) override { return firstAction(s); }
  void lastAction(float) override {}
  void seedExperiences(const std::vector<rl_common::Experience>& e) override { seeds = e; }
};
}  // namespace

TEST(DiscretizationAgent, BinsAsTheOriginal) {
  auto rec = std::make_unique<Recorder>();
  Recorder* r = rec.get();
  // Feature 0: range 10 in 5 bins (factor 2); feature 1 stays continuous (per-feature 0).
  rl_agent::DiscretizationAgent agent(std::move(rec), {5, 0}, {0, 0}, {10, 1});
  agent.firstAction({3.1f, 0.37f});       // int((3.1 + 1) / 2) = 2 -> 4
  agent.nextAction(0.0f, {2.9f, 0.5f});   // int(3.9 / 2) = 1 -> 2
  agent.nextAction(0.0f, {-0.9f, 0.5f});  // int((−0.9 − 1) / 2) = 0 -> 0
  agent.nextAction(0.0f, {-3.5f, 0.5f});  // int(−4.5 / 2) = −2 -> −4
  ASSERT_EQ(r->seen.size(), 4u);
  EXPECT_FLOAT_EQ(r->seen[0][0], 4.0f);
  EXPECT_FLOAT_EQ(r->seen[0][1], 0.37f);
  EXPECT_FLOAT_EQ(r->seen[1][0], 2.0f);
  EXPECT_FLOAT_EQ(r->seen[2][0], 0.0f);
  EXPECT_FLOAT_EQ(r->seen[3][0], -4.0f);
  agent.seedExperiences({{{3.1f, 0.0f}, 0, 1.0f, {9.9f, 1.0f}, false}});
  ASSERT_EQ(r->seeds.size(), 1u);
  EXPECT_FLOAT_EQ(r->seeds[0].s[0], 4.0f);
  EXPECT_FLOAT_EQ(r->seeds[0].next[0], 10.0f);
  EXPECT_THROW(agent.firstAction({1.0f}), std::invalid_argument);
  EXPECT_THROW(rl_agent::DiscretizationAgent(nullptr, {5}, {0}, {1}), std::invalid_argument);
}

TEST(DiscretizationAgent, RegistryWrapsModelFreeAgentsWithNstates) {
  rl_agent::AgentOptions o;
  o.agent = "qlearner";
  o.nstates = {4};
  rl_common::EnvironmentDescription d;
  d.numActions = 2;
  d.minFeatures = {0.0f};
  d.maxFeatures = {1.0f};
  auto agent = rl_agent::makeAgent(o, d);
  EXPECT_NE(dynamic_cast<rl_agent::DiscretizationAgent*>(agent.get()), nullptr);
  o.nstates = {0};
  EXPECT_EQ(dynamic_cast<rl_agent::DiscretizationAgent*>(rl_agent::makeAgent(o, d).get()), nullptr);
}
