// The agent conformance suite (as rl_env's for environments): every agent of the registry,
// built by makeAgent as the programs build it, on the slippery two-room grid (a stochastic
// episodic task with a true model, so that `optimal` runs too). Each agent must have an
// expectation below: registering an agent without one fails the suite.
//
// Checked for each: actions in range over many episodes; the same seeds give the same
// trajectory; the episode protocol (seed experiences first, episodes that end on their first
// step, a long episode cut without lastAction, firstAction after lastAction); and the policy
// file round trip where the agent saves one (saved, loaded by savedpolicy, saved again: the
// same bytes; savedpolicy acts greedily on it), or no file where it does not.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

#include "corridor.h"
#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/policy_file.h"
#include "rl_agent/agent/saved_policy.h"
#include "small_mdps.h"

namespace {

using rl_common::Agent;
using rl_common::State;
using test_mdps::TwoRoomGrid;

struct Expectation {
  std::vector<std::string> options;  ///< beyond --agent: a fixed planning budget, a policy file
  bool savesPolicy;                  ///< savePolicy writes a policy file
};

// A policy file for savedpolicy: Q favours East in the first room and North in the second.
std::string fixturePolicy() {
  static const std::string path = [] {
    const std::string p = ::testing::TempDir() + "rl_agent_conformance_fixture.pol";
    rl_agent::PolicyFile::Table q;
    for (const State& s : TwoRoomGrid().reachableStates()) {
      q[s] = s[0] < TwoRoomGrid::kWallX ? std::vector<float>{0, 0, 1, 0}
                                        : std::vector<float>{1, 0, 0, 0};
    }
    rl_agent::PolicyFile::write(p, 2, 4, q);
    return p;
  }();
  return path;
}

const std::map<std::string, Expectation>& expectations() {
  static const std::map<std::string, Expectation> e = {
      {"qlearner", {{}, true}},
      {"sarsa", {{}, true}},
      {"dyna", {{"--k", "5"}, true}},
      // Synchronous UCT with a fixed budget: real time would make a run depend on the clock.
      {"texplore", {{"--rollouts", "30", "--v", "1", "--n", "3"}, true}},
      {"modelbased", {{"--rollouts", "30"}, true}},
      {"rmax", {{}, true}},
      {"savedpolicy", {{"--filename", fixturePolicy()}, true}},
      {"optimal", {{}, false}},
  };
  return e;
}

TEST(AgentConformanceCases, EveryRegisteredAgentHasAnExpectation) {
  const std::vector<std::string> names = rl_agent::agentRegistry().names();
  for (const std::string& n : names) {
    EXPECT_EQ(expectations().count(n), 1u) << "agent '" << n << "' has no expectation";
  }
  EXPECT_EQ(names.size(), expectations().size()) << "an expectation names an unknown agent";
}

class AgentConformance : public ::testing::TestWithParam<std::string> {
 protected:
  std::unique_ptr<Agent> make(std::uint64_t seed) const {
    rl_agent::AgentOptions o =
        test_corridor::parseOptions(GetParam(), expectations().at(GetParam()).options);
    o.seed = seed;
    return rl_agent::makeAgent(o, TwoRoomGrid::describe(), &model_);
  }
  bool savesPolicy() const { return expectations().at(GetParam()).savesPolicy; }

  TwoRoomGrid model_{0.2};  // what `optimal` plans on (the slip of the grids below)
};

// Episodes of at most `maxSteps` on a grid slipping with `envSeed`; every action taken.
std::vector<int> play(Agent& agent, std::uint64_t envSeed, int episodes, int maxSteps) {
  TwoRoomGrid env(0.2, envSeed);
  std::vector<int> actions;
  for (int e = 0; e < episodes; ++e) {
    int a = agent.firstAction(env.reset());
    for (int t = 1; t <= maxSteps; ++t) {
      actions.push_back(a);
      bool terminal = false;
      const float r = env.step(a, &terminal);
      if (terminal) {
        agent.lastAction(r);
        break;
      }
      if (t == maxSteps) break;
      a = agent.nextAction(r, env.state());
    }
  }
  return actions;
}

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_P(AgentConformance, ActionsStayInRange) {
  const auto agent = make(3);
  const std::vector<int> actions = play(*agent, 4, 12, 80);
  ASSERT_FALSE(actions.empty());
  std::map<int, int> used;
  for (int a : actions) {
    ASSERT_GE(a, 0);
    ASSERT_LT(a, TwoRoomGrid::describe().numActions);
    ++used[a];
  }
  EXPECT_GE(used.size(), 2u) << "one action only in " << actions.size() << " steps";
}

TEST_P(AgentConformance, SameSeedsGiveTheSameTrajectory) {
  const auto a = make(11), b = make(11);
  const std::vector<int> first = play(*a, 5, 6, 60), second = play(*b, 5, 6, 60);
  EXPECT_EQ(first, second);
}

TEST_P(AgentConformance, FollowsTheEpisodeProtocol) {
  const auto agent = make(7);
  // Seed experiences before the first action (the original's seedExp).
  TwoRoomGrid env(0.2, 8);
  std::vector<rl_common::Experience> seeds;
  State s = env.reset();
  for (int a = 0; a < 4; ++a) {
    rl_common::Experience x;
    x.s = s;
    x.action = a;
    x.next = TwoRoomGrid::move(s, a);
    x.reward = -1.0f;
    x.terminal = false;
    seeds.push_back(x);
  }
  agent->seedExperiences(seeds);
  // An episode that ends on its first step, twice in a row: firstAction, lastAction.
  for (int i = 0; i < 2; ++i) {
    const int a = agent->firstAction({6.0f, 3.0f});
    EXPECT_GE(a, 0);
    EXPECT_LT(a, 4);
    agent->lastAction(-1.0f);
  }
  // A long episode cut without lastAction (a step limit), then a new one.
  const std::vector<int> cut = play(*agent, 9, 1, 300);
  EXPECT_LE(cut.size(), 300u);
  const std::vector<int> next = play(*agent, 10, 3, 100);
  EXPECT_FALSE(next.empty());
}

TEST_P(AgentConformance, PolicyFileRoundTrip) {
  const auto agent = make(5);
  play(*agent, 6, 8, 80);
  const std::string saved = ::testing::TempDir() + "rl_agent_conformance_" + GetParam() + ".pol";
  const std::string again = saved + ".again";
  std::remove(saved.c_str());
  std::remove(again.c_str());
  agent->savePolicy(saved);
  if (!savesPolicy()) {
    EXPECT_TRUE(contents(saved).empty()) << GetParam() << " wrote a policy file";
    return;
  }
  const rl_agent::PolicyFile::Contents file = rl_agent::PolicyFile::read(saved);
  EXPECT_EQ(file.numFeatures, 2);
  EXPECT_EQ(file.numActions, 4);
  ASSERT_FALSE(file.q.empty());
  rl_agent::SavedPolicy replay(4, 2, saved, 1);
  EXPECT_EQ(replay.numStates(), file.q.size());
  for (const auto& [state, q] : file.q) {
    const int a = replay.firstAction(state);
    EXPECT_TRUE(replay.lastActionKnown());
    EXPECT_EQ(q[a], *std::max_element(q.begin(), q.end())) << "not greedy on the file";
  }
  replay.savePolicy(again);
  EXPECT_EQ(contents(again), contents(saved));
  std::remove(saved.c_str());
  std::remove(again.c_str());
}

INSTANTIATE_TEST_SUITE_P(EveryAgent, AgentConformance,
                         ::testing::ValuesIn(rl_agent::agentRegistry().names()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return info.param;
                         });

}  // namespace
