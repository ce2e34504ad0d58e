// The model and planner registries' facts, the planning loops they build (synchronous and real
// time behind one interface), the action selector and the experience log of ModelBasedAgent.
#include "rl_agent/planner/planning_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "rl_agent/agent/action_selector.h"
#include "rl_agent/agent/experience_log.h"
#include "rl_agent/model/model_registry.h"
#include "rl_agent/model/tabular_model.h"
#include "rl_agent/planner/planner_registry.h"

using namespace rl_agent;

namespace {

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

std::unique_ptr<rl_common::MDPModel> tabular() {
  TabularModel::Config c;
  c.numActions = 3;
  c.numFeatures = 1;
  return std::make_unique<TabularModel>(c);
}

PlannerSettings settings(long rollouts, int threads = 1) {
  PlannerSettings s;
  s.search.numActions = 3;
  s.search.featMin = {0.0f};
  s.search.featMax = {7.0f};
  s.dp.numActions = 3;
  s.dp.featMin = {0.0f};
  s.dp.featMax = {7.0f};
  s.rollouts = rollouts;
  s.searchThreads = threads;
  s.seed = 3;
  return s;
}

rl_common::Experience moveRight(float x) { return {{x}, 1, 0.0f, {x + 1.0f}, false}; }

}  // namespace

TEST(ModelRegistry, FactsSayWhichExplorersAndInputsEachModelTakes) {
  EXPECT_EQ(modelRegistry().names(), (std::vector<std::string>{"m5tree", "tabular", "tree"}));
  EXPECT_EQ(modelRegistry().canonical("c45tree"), "tree");
  EXPECT_TRUE(contains(explorersFor("tree"), "variancenovelty"));
  EXPECT_TRUE(contains(explorersFor("tabular"), "unknown"));
  EXPECT_FALSE(contains(explorersFor("tabular"), "variancenovelty"));
  EXPECT_TRUE(contains(explorersFor("m5tree"), "boltzmann"));
  EXPECT_FALSE(contains(explorersFor("m5tree"), "unknown"));
  try {
    checkModelExplorer("m5tree", "unknown");
    FAIL() << "m5tree took --explore unknown";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not available with --model m5tree; valid: boltzmann"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(checkModelExplorer("tabular", "unknown"));
  // A continuous-input model needs a grid for dynamic programming, not for search.
  EXPECT_THROW(checkModelGrid("m5tree", "vi", false, false), std::invalid_argument);
  EXPECT_NO_THROW(checkModelGrid("m5tree", "vi", false, true));
  EXPECT_NO_THROW(checkModelGrid("m5tree", "uct", true, false));
  EXPECT_NO_THROW(checkModelGrid("tree", "vi", false, false));
}

TEST(ModelRegistry, BuildsEachModelWithItsSwitch) {
  ModelSettings s;
  s.numActions = 3;
  s.featMin = {0.0f};
  s.featMax = {7.0f};
  s.combination = "best";
  s.explore = "unknown";
  const auto table = modelRegistry().create("tabular", s);
  EXPECT_NE(table->tabular, nullptr);
  EXPECT_EQ(table->exploration, nullptr);
  // Optimism on for an unknown state-action: the reward is rmax; off: not.
  s.rmax = 5.0f;
  s.m = 5;
  const auto optimistic = modelRegistry().create("tabular", s);
  EXPECT_FLOAT_EQ(optimistic->model->view()->query({0.0f}, 0).reward, 5.0f);
  optimistic->setIntrinsicEnabled(false);
  EXPECT_LT(optimistic->model->view()->query({0.0f}, 0).reward, 1.0f);
  s.explore = "variancenovelty";
  EXPECT_THROW(modelRegistry().create("tabular", s), std::invalid_argument);
  EXPECT_THROW(modelRegistry().create("tree", s), std::invalid_argument);  // no explorer given
}

TEST(PlannerRegistry, FactsAndTheLoopsTheyBuild) {
  const PlannerRegistry& reg = plannerRegistry();
  EXPECT_EQ(
      reg.namesWith(kSearchPlannerFact),
      (std::vector<std::string>{"delayed-parallel-uct", "delayed-uct", "parallel-uct", "uct"}));
  EXPECT_EQ(reg.namesWith(kRealTimePlannerFact),
            (std::vector<std::string>{"delayed-parallel-uct", "parallel-uct"}));
  EXPECT_EQ(reg.canonical("realtimeuct"), "parallel-uct");
  EXPECT_EQ(reg.canonical("valueiteration"), "vi");

  // The real-time planner plans synchronously with a rollout budget.
  EXPECT_FALSE(makePlanningLoop("parallel-uct", settings(5), tabular())->realTime());
  auto realTime = makePlanningLoop("parallel-uct", settings(0, 2), tabular());
  EXPECT_TRUE(realTime->realTime());
  int trees = 0;
  realTime->forEachSearchPlanner([&](UctPlanner&) { ++trees; });
  EXPECT_EQ(trees, 2);  // one search tree per thread
  realTime->stop();

  auto vi = makePlanningLoop("vi", settings(0), tabular());
  EXPECT_NE(vi->statePlanner(), nullptr);
  int searched = 0;
  vi->forEachSearchPlanner([&](UctPlanner&) { ++searched; });
  EXPECT_EQ(searched, 0);
  PlannerSettings withHistory = settings(0);
  withHistory.search.history = 2;
  EXPECT_THROW(makePlanningLoop("pi", withHistory, tabular()), std::invalid_argument);
  EXPECT_THROW(makePlanningLoop("astar", settings(0), tabular()), std::invalid_argument);
}

TEST(SyncPlanningLoop, LazyViewsReachThePlannerAtTheNextFilter) {
  for (const bool lazy : {false, true}) {
    PlannerSettings s = settings(10);
    s.lazyViews = lazy;
    auto loop = makePlanningLoop("uct", s, tabular());
    std::uint64_t version = 0;
    const auto readVersion = [&] {
      loop->forEachSearchPlanner([&](UctPlanner& p) { version = p.modelVersion(); });
      return version;
    };
    const std::uint64_t start = readVersion();
    loop->learn(moveRight(0.0f));
    EXPECT_EQ(readVersion(), lazy ? start : start + 1) << "lazy " << lazy;
    // Nothing changed in the filter: only a waiting update makes a new view.
    loop->filterViews(nullptr, [] { return PlanningLoop::ViewFilter(); });
    EXPECT_EQ(readVersion(), start + 1) << "lazy " << lazy;
    loop->filterViews(nullptr, [] { return PlanningLoop::ViewFilter(); });
    EXPECT_EQ(readVersion(), start + 1) << "lazy " << lazy;
    const int action = loop->act({0.0f}, PlanningLoop::Clock::now(), true);
    EXPECT_GE(action, 0);
    EXPECT_LT(action, 3);
    EXPECT_EQ(loop->lastRollouts(), 10);
    EXPECT_EQ(loop->qValues({0.0f}).size(), 3u);
    // No planning wanted (random actions): no rollouts.
    loop->act({0.0f}, PlanningLoop::Clock::now(), false);
    EXPECT_EQ(loop->lastRollouts(), 0);
  }
}

TEST(ActionSelector, EachModeChoosesAsItSays) {
  rl_common::Random rng(5);
  const std::vector<double> q{0.0, 0.0, 10.0, 0.0};
  const ActionSelector greedy(ActionSelector::Mode::Greedy, 4, 0.0, 1.0);
  const ActionSelector never(ActionSelector::Mode::EpsilonGreedy, 4, 0.0, 1.0);
  const ActionSelector always(ActionSelector::Mode::EpsilonGreedy, 4, 1.0, 1.0);
  const ActionSelector random(ActionSelector::Mode::Random, 4, 0.0, 1.0);
  const ActionSelector cold(ActionSelector::Mode::Boltzmann, 4, 0.0, 0.2);
  EXPECT_TRUE(greedy.needsPlanner());
  EXPECT_FALSE(random.needsPlanner());
  std::set<int> epsilonActions, randomActions;
  for (int i = 0; i < 400; ++i) {
    EXPECT_EQ(greedy.choose(1, q, rng), 1);
    EXPECT_EQ(never.choose(1, q, rng), 1);
    EXPECT_EQ(cold.choose(1, q, rng), 2);  // softmax at tau 0.2 of a gap of 10
    epsilonActions.insert(always.choose(1, q, rng));
    randomActions.insert(random.choose(1, q, rng));
  }
  EXPECT_EQ(epsilonActions, (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(randomActions, (std::set<int>{0, 1, 2, 3}));
  EXPECT_EQ(cold.choose(1, {1.0, 2.0}, rng), 1);  // values of the wrong size: the planner's
  EXPECT_THROW(ActionSelector(ActionSelector::Mode::EpsilonGreedy, 4, 1.5, 1.0),
               std::invalid_argument);
  EXPECT_THROW(ActionSelector(ActionSelector::Mode::Boltzmann, 4, 0.0, 0.0), std::invalid_argument);
  Explorer explorer;
  explorer.boltzmann = true;
  explorer.randomActions = true;
  EXPECT_EQ(ActionSelector::forExplorer(explorer, 4, 0.1).mode(), ActionSelector::Mode::Random);
}

TEST(ExperienceLog, RelabelsStepsAndKeepsSeeds) {
  ExperienceLog log;
  log.record(true);
  log.addSeeds({{{0.0f}, 0, 7.0f, {0.0f}, false}});
  log.addStep(moveRight(0.0f));
  log.addStep(moveRight(1.0f));
  EXPECT_EQ(log.steps(), 2u);
  const auto replay = log.relabel({1.0f, 2.0f});
  ASSERT_EQ(replay.size(), 3u);
  EXPECT_FLOAT_EQ(replay[0].reward, 7.0f);  // the seed keeps its reward
  EXPECT_FLOAT_EQ(replay[1].reward, 1.0f);
  EXPECT_FLOAT_EQ(replay[2].reward, 2.0f);
  EXPECT_THROW(log.relabel({1.0f}), std::invalid_argument);

  ExperienceLog late;
  late.addStep(moveRight(0.0f));
  EXPECT_THROW(late.record(true), std::logic_error);  // one experience would be missing
  EXPECT_THROW(late.relabel({}), std::logic_error);
}
