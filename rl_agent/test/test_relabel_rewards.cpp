// ModelBasedAgent::relabelRewards: after a reward-free phase the agent is given the task's
// reward of every transition it had, and its model equals the model of an agent that saw those
// rewards all along.
#include <gtest/gtest.h>

#include <memory>
#include <set>
#include <utility>
#include <vector>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "small_mdps.h"

namespace {

using rl_agent::ModelBasedAgent;
using rl_common::State;

// A task reward that varies over the grid: the x coordinate of the state reached.
float taskReward(const State& next) { return next[0]; }

rl_agent::AgentOptions randomExplorer(const std::string& model, const std::string& planner) {
  rl_agent::AgentOptions o;
  o.agent = "modelbased";
  o.model = model;
  o.planner = planner;
  o.explore = "random";  // actions from the agent's own stream: the same in both runs
  o.combo = model == "tree" ? "average" : "best";
  o.nmodels = model == "tree" ? 3 : 1;
  o.rollouts = planner == "parallel-uct" ? 0 : 20;
  o.actrate = 200.0f;
  o.seed = 5;
  return o;
}

struct Episodes {
  std::unique_ptr<rl_common::Agent> agent;
  std::set<std::pair<State, int>> visited;
  std::vector<float> rewards;  ///< the task's reward of every step
};

// `steps` steps on the two-room grid; the agent sees the task's reward if `seeReward`.
Episodes runSteps(const rl_agent::AgentOptions& o, int steps, bool seeReward, bool record) {
  Episodes r;
  r.agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  auto* mb = dynamic_cast<ModelBasedAgent*>(r.agent.get());
  if (record) mb->recordExperiences(true);
  test_mdps::TwoRoomGrid env(0.2, 9);
  State s = env.reset();
  int a = r.agent->firstAction(s);
  for (int t = 0; t < steps; ++t) {
    r.visited.insert({s, a});
    bool terminal = false;
    env.step(a, &terminal);
    const State next = terminal ? env.reset() : env.state();
    const float reward = taskReward(env.state());
    r.rewards.push_back(reward);
    if (terminal) {
      r.agent->lastAction(seeReward ? reward : 0.0f);
      a = r.agent->firstAction(next);
    } else {
      a = r.agent->nextAction(seeReward ? reward : 0.0f, next);
    }
    s = next;
  }
  return r;
}

float predictedReward(const rl_common::Agent& agent, const State& s, int a) {
  const auto& mb = dynamic_cast<const ModelBasedAgent&>(agent);
  return mb.learnedModelView()->query(s, a).reward;
}

void expectRelabelledEqualsInformed(const rl_agent::AgentOptions& seen,
                                    const rl_agent::AgentOptions& relabelled) {
  const int steps = 150;
  Episodes informed = runSteps(seen, steps, true, false);
  Episodes blind = runSteps(relabelled, steps, false, true);
  ASSERT_EQ(informed.visited, blind.visited) << "the two runs took different actions";
  auto& mb = dynamic_cast<ModelBasedAgent&>(*blind.agent);
  EXPECT_EQ(mb.recordedSteps(), blind.rewards.size());
  int differed = 0;
  for (const auto& [s, a] : blind.visited) {
    differed += predictedReward(*informed.agent, s, a) != predictedReward(*blind.agent, s, a);
  }
  EXPECT_GT(differed, 0) << "rewards hidden or not, the models predicted the same";
  mb.relabelRewards(blind.rewards);
  for (const auto& [s, a] : blind.visited) {
    EXPECT_FLOAT_EQ(predictedReward(*informed.agent, s, a), predictedReward(*blind.agent, s, a))
        << "state (" << s[0] << ", " << s[1] << "), action " << a;
  }
  // The agent goes on acting on the rebuilt model.
  State s{0.0f, 0.0f};
  int a = blind.agent->firstAction(s);
  for (int t = 0; t < 5; ++t) {
    ASSERT_GE(a, 0);
    ASSERT_LT(a, 4);
    a = blind.agent->nextAction(0.0f, s);
  }
}

}  // namespace

TEST(RelabelRewards, TreeModelEqualsTheModelThatSawTheRewards) {
  const auto o = randomExplorer("tree", "uct");
  expectRelabelledEqualsInformed(o, o);
}

TEST(RelabelRewards, TabularModelEqualsTheModelThatSawTheRewards) {
  const auto o = randomExplorer("tabular", "vi");
  expectRelabelledEqualsInformed(o, o);
}

TEST(RelabelRewards, RealTimeAgentRestartsOnTheRebuiltModel) {
  // The model does not depend on the planner: a real-time agent relabelled equals a
  // synchronous one that saw the rewards (the real-time agent's actions are its own random
  // stream too).
  expectRelabelledEqualsInformed(randomExplorer("tree", "uct"),
                                 randomExplorer("tree", "parallel-uct"));
}

TEST(RelabelRewards, NeedsRecordingAndOneRewardPerStep) {
  const auto o = randomExplorer("tree", "uct");
  Episodes notRecorded = runSteps(o, 10, false, false);
  auto& plain = dynamic_cast<ModelBasedAgent&>(*notRecorded.agent);
  EXPECT_THROW(plain.relabelRewards(notRecorded.rewards), std::logic_error);
  Episodes recorded = runSteps(o, 10, false, true);
  auto& mb = dynamic_cast<ModelBasedAgent&>(*recorded.agent);
  EXPECT_THROW(mb.relabelRewards(std::vector<float>(3, 1.0f)), std::invalid_argument);
  // Recording that starts late would rebuild a model without the earlier experiences.
  EXPECT_THROW(plain.recordExperiences(true), std::logic_error);
}
