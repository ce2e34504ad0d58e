// The Environment and Agent interfaces driven through the original's episode protocol with
// small hand-written implementations: describe() mirrors the declared ranges, and an
// episode calls firstAction, nextAction and lastAction in the original's order.
#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include <string>
#include <vector>

#include "rl_common/agent.h"
#include "rl_common/environment.h"

namespace {

// A 1-D corridor of length 4: action 1 moves right, 0 left; reaching cell 3 ends the episode.
class Corridor : public rl_common::Environment {
 public:
  const rl_common::State& sensation() const override { return s_; }
  float apply(int a) override {
    if (a < 0 || a >= 2) throw std::out_of_range("Corridor::apply(): bad action");
    s_[0] = std::max(0.0f, std::min(3.0f, s_[0] + (a == 1 ? 1.0f : -1.0f)));
    return terminal() ? 1.0f : 0.0f;
  }
  bool terminal() const override { return s_[0] >= 3.0f; }
  void reset() override { s_ = {0.0f}; }
  int numActions() const override { return 2; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override {
    *min = {0.0f};
    *max = {3.0f};
  }
  void getMinMaxReward(float* min, float* max) const override {
    *min = 0.0f;
    *max = 1.0f;
  }
  std::string name() const override { return "Corridor"; }
  bool isStochastic() const override { return false; }

 private:
  rl_common::State s_{0.0f};
};

// Records the calls it receives and always moves right.
class Recorder : public rl_common::Agent {
 public:
  int firstAction(const rl_common::State& s) override {
    calls.push_back("first " + std::to_string(int(s[0])));
    return 1;
  }
  int nextAction(float r, const rl_common::State& s) override {
    calls.push_back("next " + std::to_string(int(r)) + " " + std::to_string(int(s[0])));
    return 1;
  }
  void lastAction(float r) override { calls.push_back("last " + std::to_string(int(r))); }
  std::vector<std::string> calls;
};

}  // namespace

TEST(Interfaces, DescribeMirrorsDeclaredRanges) {
  Corridor env;
  const auto d = env.describe();
  EXPECT_EQ(d.numActions, 2);
  EXPECT_EQ(d.numFeatures(), 1u);
  EXPECT_EQ(d.maxFeatures, std::vector<float>{3.0f});
  EXPECT_FLOAT_EQ(d.rewardRange(), 1.0f);
  EXPECT_TRUE(d.episodic);
  EXPECT_FALSE(d.stochastic);
  EXPECT_EQ(d.title, "Environment: Corridor\n");
}

TEST(Interfaces, EpisodeProtocolOrder) {
  Corridor env;
  Recorder agent;
  int a = agent.firstAction(env.sensation());
  float r = env.apply(a);
  while (!env.terminal()) {
    a = agent.nextAction(r, env.sensation());
    r = env.apply(a);
  }
  agent.lastAction(r);
  EXPECT_EQ(agent.calls, (std::vector<std::string>{"first 0", "next 0 1", "next 0 2", "last 1"}));
  EXPECT_THROW(env.apply(2), std::out_of_range);
}
