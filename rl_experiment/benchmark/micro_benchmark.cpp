// Micro-benchmarks (Google Benchmark) of the parts of a TEXPLORE-VANIR step on LightWorld, and
// the limit of the UCT loop: rollouts on a model whose predictions are all cached already.
//
//   rl_experiment_micro_benchmark [--benchmark_filter=REGEX] [--benchmark_min_time=0.5]
//
// Every case learns from the same 1000-step random walk (rl_experiment::scriptedLightWorldStream,
// seed 1) with the forest of `--agent texplore` (5 trees, average, featPct 0.2) and VANIR's
// rewards v 1, n 3. Prints figures; never a pass/fail verdict.
//  - TreeUpdate: instances 1000..1099 of a walk added one at a time to a C4.5 tree that holds
//    the first 1000 (built outside the timing); items/s is instances per second.
//  - ForestQuery: one planner query of the exploration model (17 feature forests, reward and
//    terminal forests, variance from the same descent, novelty) at a state of the walk.
//  - NoveltyQuery: the novelty of a state-action against the walk's visited set.
//  - Rollout: one UCT rollout (depth 200) from a state of the walk, the model updated before
//    every step's 100 rollouts as in the agent (so predictions are re-queried).
//  - RolloutCached: the same with the model fixed and its predictions cached by a warm-up
//    pass: the cost of the UCT loop alone (tables, selection, sampling, backups).
#include <benchmark/benchmark.h>

#include <memory>
#include <vector>

#include "rl_agent/model/c45_tree.h"
#include "rl_agent/model/exploration_model.h"
#include "rl_agent/planner/uct_planner.h"
#include "rl_agent/reward/novelty_reward.h"
#include "rl_agent/reward/variance_reward.h"
#include "rl_env/env/light_world.h"
#include "rl_experiment/eval/scripted_stream.h"

namespace {

using rl_env::LightWorld;

const std::vector<rl_common::Experience>& walk() {
  static const std::vector<rl_common::Experience> data = [] {
    rl_experiment::ScriptedStreamConfig c;
    c.stream = "walk";
    c.steps = 1000;
    return rl_experiment::scriptedLightWorldStream(c, 1);
  }();
  return data;
}

rl_agent::FactoredModel::Config modelConfig() {
  const LightWorld env(1, true);
  rl_agent::FactoredModel::Config c;
  env.getMinMaxFeatures(&c.featMin, &c.featMax);
  c.numActions = LightWorld::kNumActions;
  c.episodic = false;
  c.forest.numTrees = 5;
  c.forest.combination = rl_agent::Combination::Average;
  c.forest.tree.featPct = 0.2;
  return c;
}

std::unique_ptr<rl_agent::ExplorationModel> vanirModel(std::size_t experiences) {
  rl_agent::ExplorationModel::Rewards rewards{std::make_shared<rl_agent::NoveltyReward>(3.0),
                                              std::make_shared<rl_agent::VarianceReward>(1.0)};
  auto m = std::make_unique<rl_agent::ExplorationModel>(modelConfig(), 7, rewards);
  for (std::size_t i = 0; i < experiences && i < walk().size(); ++i) m->update({walk()[i]});
  return m;
}

rl_agent::UctPlanner::Config plannerConfig() {
  const auto m = modelConfig();
  rl_agent::UctPlanner::Config c;
  c.numActions = LightWorld::kNumActions;
  c.gamma = 0.99;
  c.lambda = 1.0;
  c.rewardRange = LightWorld::kExitReward;
  c.featMin = m.featMin;
  c.featMax = m.featMax;
  return c;
}

void TreeUpdate(benchmark::State& state) {
  rl_experiment::ScriptedStreamConfig wc;
  wc.steps = 1100;
  const auto data = rl_experiment::scriptedLightWorldStream(wc, 1);
  auto input = [](const rl_common::Experience& e) {
    std::vector<float> x(e.s.begin(), e.s.end());
    for (int a = 0; a < LightWorld::kNumActions; ++a) x.push_back(a == e.action ? 1.0f : 0.0f);
    return x;
  };
  // The key-north light's change: the feature with the most model error.
  auto output = [](const rl_common::Experience& e) {
    return e.next[LightWorld::kKeyN] - e.s[LightWorld::kKeyN];
  };
  rl_agent::C45Tree::Config tc;
  tc.featPct = 0.2;
  for (auto _ : state) {
    state.PauseTiming();
    rl_agent::C45Tree tree(tc, 3);
    for (std::size_t i = 0; i < 1000; ++i) tree.addInstance(input(data[i]), output(data[i]));
    state.ResumeTiming();
    for (std::size_t i = 1000; i < data.size(); ++i) {
      benchmark::DoNotOptimize(tree.addInstance(input(data[i]), output(data[i])));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(data.size() - 1000));
}
BENCHMARK(TreeUpdate);

/// Calls f(state, action) for the walk's states in a scattered order, actions in turn.
template <class F>
void overWalk(benchmark::State& state, F f) {
  std::size_t i = 0;
  for (auto _ : state) {
    f(walk()[(i * 7) % walk().size()].s, static_cast<int>(i % LightWorld::kNumActions));
    ++i;
  }
}

void ForestQuery(benchmark::State& state) {
  const auto model = vanirModel(1000);
  const auto view = model->view();
  overWalk(state,
           [&](const rl_common::State& s, int a) { benchmark::DoNotOptimize(view->query(s, a)); });
}
BENCHMARK(ForestQuery);

void NoveltyQuery(benchmark::State& state) {
  const auto model = vanirModel(1000);
  const auto view = model->explorationView();
  overWalk(state, [&](rl_common::State s, int a) {
    s[LightWorld::kEw] += 1.0f;  // a neighbour, usually not visited with this action
    benchmark::DoNotOptimize(view->visited().novelty(s, a));
  });
}
BENCHMARK(NoveltyQuery);

void Rollout(benchmark::State& state) {
  auto model = vanirModel(500);
  rl_agent::UctPlanner planner(plannerConfig(), 11);
  std::size_t step = 500;
  for (auto _ : state) {
    state.PauseTiming();
    // A new experience and model version every 100 rollouts, as the agent's steps.
    const auto& e = walk()[step % walk().size()];
    model->update({e});
    planner.setModel(model->view());
    ++step;
    state.ResumeTiming();
    planner.plan(e.next, rl_common::PlanningBudget::ofRollouts(100));
  }
  state.SetItemsProcessed(state.iterations() * 100);
}
BENCHMARK(Rollout)->Unit(benchmark::kMillisecond);

void RolloutCached(benchmark::State& state) {
  const auto model = vanirModel(1000);
  rl_agent::UctPlanner::Config c = plannerConfig();
  c.maxStates = 2000000;
  c.maxCachedPredictions = 4000000;
  rl_agent::UctPlanner planner(c, 11);
  planner.setModel(model->view());
  const rl_common::State root = walk().back().next;
  planner.plan(root, rl_common::PlanningBudget::ofRollouts(20000));  // warm the caches
  for (auto _ : state) planner.plan(root, rl_common::PlanningBudget::ofRollouts(100));
  state.SetItemsProcessed(state.iterations() * 100);
  state.counters["cached_predictions"] = static_cast<double>(planner.numCachedPredictions());
}
BENCHMARK(RolloutCached)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
