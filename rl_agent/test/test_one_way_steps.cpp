// TEXPLORE-VANIR puts off one-way steps (StepDeferral): on a corridor with a key that cannot
// be put down, the agent that learned the pickup is one-way leaves the next key on the floor.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>

#include "corridor.h"
#include "rl_agent/agent/model_based_agent.h"

using rl_agent::AgentOptions;
using rl_agent::ModelBasedAgent;
using rl_common::State;

namespace {

/// Cells 0..4, the key at `keyAt`. Actions: left (0), right (1), pickup (2), wait (3). State
/// {x, have_key, light_n, light_s}: the key's two lights read 5 at the key, one less per cell
/// away from it (as LightWorld's), and 0 once it is held. Not episodic; the test restarts the world
/// to put the key back.
rl_common::EnvironmentDescription keyCorridor() {
  rl_common::EnvironmentDescription d;
  d.numActions = 4;
  d.minFeatures = {0, 0, 0, 0};
  d.maxFeatures = {4, 1, 5, 5};
  d.minReward = 0.0f;
  d.maxReward = 1.0f;
  d.episodic = false;
  return d;
}

struct World {
  int keyAt = 2;
  int x = 0;
  bool key = false;
  State state() const {
    const float light = key ? 0.0f : 5.0f - static_cast<float>(std::abs(x - keyAt));
    return {float(x), key ? 1.0f : 0.0f, light, light};
  }
  /// Returns true if the action picked the key up.
  bool apply(int a) {
    if (a == 0) x = std::max(0, x - 1);
    if (a == 1) x = std::min(4, x + 1);
    if (a == 2 && x == keyAt && !key) return key = true;
    return false;
  }
};

/// Runs `steps` steps from a fresh world with the key at `keyAt` (the first action starts a
/// new episode for the agent); returns the step of each pickup.
std::vector<int> live(ModelBasedAgent& agent, int steps, int keyAt) {
  World w;
  w.keyAt = keyAt;
  std::vector<int> pickups;
  int a = agent.firstAction(w.state());
  for (int t = 0; t < steps; ++t) {
    if (w.apply(a)) pickups.push_back(t);
    a = agent.nextAction(0.0f, w.state());
  }
  agent.lastAction(0.0f);
  return pickups;
}

AgentOptions vanir(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"--rollouts", "50", "--v", "1", "--n", "3"};
  args.insert(args.end(), extra.begin(), extra.end());
  AgentOptions o = test_corridor::parseOptions("texplore", args);
  o.seed = 4;
  return o;
}

}  // namespace

TEST(OneWaySteps, DeferredOnlyWhenAsked) {
  EXPECT_EQ(ModelBasedAgent(vanir({}), keyCorridor()).deferSteps(), 0);  // as the original
  EXPECT_EQ(ModelBasedAgent(vanir({"--defer", "300"}), keyCorridor()).deferSteps(), 300);
  EXPECT_EQ(ModelBasedAgent(vanir({"--defer", "0"}), keyCorridor()).deferSteps(), 0);
  EXPECT_EQ(ModelBasedAgent(vanir({"--defer", "50"}), keyCorridor()).deferSteps(), 50);
  const AgentOptions random =
      test_corridor::parseOptions("texplore", {"--rollouts", "50", "--explore", "random"});
  EXPECT_EQ(ModelBasedAgent(random, keyCorridor()).deferSteps(), 0);
  const AgentOptions greedy = test_corridor::parseOptions("texplore", {"--rollouts", "50"});
  EXPECT_EQ(ModelBasedAgent(greedy, keyCorridor()).deferSteps(), 0);
}

TEST(OneWaySteps, TheAgentThatLearnedThePickupLeavesTheNextKeyOnTheFloor) {
  // On the original's averaged forest: there the agent without the deferral takes the second
  // key within 250 steps (on the separate forest, the default, it does not on this seed).
  ModelBasedAgent agent(vanir({"--defer", "300", "--combo", "average"}), keyCorridor());
  // First life: curiosity tries the pickup early, and the key stays held for good.
  const auto first = live(agent, 200, 2);
  ASSERT_FALSE(first.empty()) << "VANIR never tried the pickup";
  ASSERT_LT(first.front(), 100) << "the pickup came too late to be confirmed one-way";
  ASSERT_NE(agent.deferral(), nullptr);
  ASSERT_EQ(agent.deferral()->signatures().size(), 1u);
  EXPECT_EQ(agent.deferral()->signatures()[0].action, 2);
  // Second life, the key in a new place: it is left on the floor for the region's steps.
  const auto second = live(agent, 250, 3);
  EXPECT_TRUE(second.empty()) << "picked up at step " << second.front();
  // Without the deferral the same agent picks the new key up.
  ModelBasedAgent original(vanir({"--defer", "0", "--combo", "average"}), keyCorridor());
  ASSERT_FALSE(live(original, 200, 2).empty());
  EXPECT_FALSE(live(original, 250, 3).empty()) << "the contrast of this test is gone";
}
