// The model-based agent with every model, planner and action-selection explorer.
#include <gtest/gtest.h>

#include <map>

#include "rl_agent/agent/agent_registry.h"
#include "rl_agent/agent/model_based_agent.h"
#include "small_mdps.h"

namespace {

rl_agent::AgentOptions options(const std::string& model, const std::string& planner,
                               const std::string& explore) {
  rl_agent::AgentOptions o;
  o.agent = "modelbased";
  o.model = model;
  o.planner = planner;
  o.explore = explore;
  o.combo = "best";
  o.nmodels = 1;
  o.m = 1;
  o.gamma = 0.95f;
  o.rollouts = 200;
  o.seed = 11;
  return o;
}

int totalSteps(rl_agent::AgentOptions o, int episodes) {
  auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  test_mdps::TwoRoomGrid env;
  int total = 0;
  for (int e = 0; e < episodes; ++e) total += test_mdps::runEpisode(*agent, env, 300);
  return total;
}

}  // namespace

TEST(ModelBasedVariants, DynamicProgrammingPlannersWithATabularModel) {
  for (const char* planner : {"vi", "pi", "sweeping"}) {
    auto o = options("tabular", planner, "unknown");
    o.rollouts = 0;
    auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
    test_mdps::TwoRoomGrid env;
    int last = 0;
    for (int e = 0; e < 15; ++e) last = test_mdps::runEpisode(*agent, env, 1000);
    EXPECT_EQ(last, 10) << planner;  // m = 1 in a deterministic grid: optimal once explored
  }
}

TEST(ModelBasedVariants, TreeModelWithValueIteration) {
  auto o = options("tree", "vi", "unknown");
  o.rollouts = 0;
  EXPECT_LT(totalSteps(o, 10), 10 * 300);  // reaches the goal
}

TEST(ModelBasedVariants, UctAndDelayedUctRun) {
  for (const char* planner : {"uct", "delayed-uct"}) {
    auto o = options("tabular", planner, "unknown");
    o.history = std::string(planner) == "delayed-uct" ? 1 : 0;
    EXPECT_LT(totalSteps(o, 8), 8 * 300) << planner;
  }
}

TEST(ModelBasedVariants, M5TreeModelRuns) {
  auto o = options("m5tree", "vi", "greedy");
  o.rollouts = 0;
  EXPECT_THROW(rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe()),
               std::invalid_argument);  // vi on a continuous model needs a state grid
  o.nstates = {6};
  auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  test_mdps::TwoRoomGrid env;
  test_mdps::runEpisode(*agent, env, 30);
  o.planner = "uct";
  o.nstates = {0};
  o.rollouts = 20;
  auto uct = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  test_mdps::runEpisode(*uct, env, 30);
  const auto* mb = dynamic_cast<rl_agent::ModelBasedAgent*>(agent.get());
  ASSERT_NE(mb, nullptr);
  EXPECT_EQ(mb->modelView(), nullptr);  // not a tree model
  EXPECT_NE(mb->learnedModelView(), nullptr);
}

TEST(ModelBasedVariants, RandomExplorerActsUniformly) {
  auto o = options("tabular", "vi", "random");
  auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  std::map<int, int> counts;
  int a = agent->firstAction({0, 0});
  for (int t = 0; t < 4000; ++t) {
    ++counts[a];
    a = agent->nextAction(0.0f, {float(t % 3), 0.0f});
  }
  for (int b = 0; b < 4; ++b) EXPECT_NEAR(counts[b] / 4000.0, 0.25, 0.03);
}

TEST(ModelBasedVariants, BoltzmannExplorerLearns) {
  auto o = options("tabular", "vi", "boltzmann");
  o.rollouts = 0;
  o.tau = 0.2f;
  // Greedy on a self-transition model with reward −1 everywhere does not explore by itself;
  // softmax over near-equal values does, and the agent reaches the goal.
  EXPECT_LT(totalSteps(o, 10), 10 * 300);
}

TEST(ModelBasedVariants, RejectsExplorersAModelCannotServe) {
  const auto d = test_mdps::TwoRoomGrid::describe();
  EXPECT_THROW(rl_agent::makeAgent(options("tabular", "vi", "variancenovelty"), d),
               std::invalid_argument);
  EXPECT_THROW(rl_agent::makeAgent(options("m5tree", "vi", "unknown"), d), std::invalid_argument);
  EXPECT_THROW(rl_agent::makeAgent(options("tabular", "bogus", "greedy"), d),
               std::invalid_argument);
}

TEST(ModelBasedVariants, SavesTheDynamicProgrammingPolicy) {
  auto o = options("tabular", "vi", "unknown");
  o.rollouts = 0;
  auto agent = rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
  test_mdps::TwoRoomGrid env;
  for (int e = 0; e < 15; ++e) test_mdps::runEpisode(*agent, env, 1000);
  const std::string f = testing::TempDir() + "rl_agent_mb_policy.pol";
  agent->savePolicy(f);
  rl_agent::AgentOptions replay;
  replay.agent = "savedpolicy";
  replay.filename = f;
  auto saved = rl_agent::makeAgent(replay, test_mdps::TwoRoomGrid::describe());
  EXPECT_EQ(test_mdps::runEpisode(*saved, env, 100), 10);
  std::remove(f.c_str());
}

TEST(ModelBasedVariants, NstatesPerFeature) {
  auto o = options("tree", "uct", "unknown");
  o.nstates = {6, 4, 1};  // three entries for two features
  try {
    rl_agent::makeAgent(o, test_mdps::TwoRoomGrid::describe());
    ADD_FAILURE() << "--nstates of the wrong length was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--nstates 6,4,1 has 3 entries"), std::string::npos)
        << e.what();
  }
  o.nstates = {6, 0};  // x binned by its cell width, y as it is: the grid is unchanged
  EXPECT_LT(totalSteps(o, 10), 10 * 300);
}
