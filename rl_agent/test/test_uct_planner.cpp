#include "rl_agent/planner/uct_planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <utility>
#include <vector>

#include "rl_common/stop_request.h"

using rl_agent::UctPlanner;
using rl_common::Experience;
using rl_common::PlanningBudget;
using rl_common::State;
using rl_common::StateActionInfo;

namespace {

/// A model given by a pure function; counts its queries and records their inputs.
class FunctionView : public rl_common::ModelView {
 public:
  using Fn = std::function<StateActionInfo(const State&, int)>;
  explicit FunctionView(Fn fn) : fn_(std::move(fn)) {}

  StateActionInfo query(const State& input, int action) const override {
    ++queries_;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      inputs_.emplace_back(input, action);
    }
    return fn_(input, action);
  }

  long queries() const { return queries_.load(); }
  std::vector<std::pair<State, int>> inputs() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return inputs_;
  }

 private:
  Fn fn_;
  mutable std::atomic<long> queries_{0};
  mutable std::mutex mutex_;
  mutable std::vector<std::pair<State, int>> inputs_;
};

StateActionInfo outcome(std::vector<std::pair<State, double>> transitions, float reward,
                        float termProb = 0.0f) {
  StateActionInfo info;
  info.transitions = std::move(transitions);
  info.reward = reward;
  info.termProb = termProb;
  info.known = true;
  return info;
}

/// States 0..5; action 1 moves right, action 0 left (0 stays at 0). Arriving at 5 pays 1 and
/// ends the episode.
StateActionInfo chain(const State& s, int a) {
  const float x = s[0];
  if (a == 1 && x >= 4.0f) {
    return outcome({{State{5.0f}, 1.0}}, 1.0f, 1.0f);
  }
  const float next = a == 1 ? x + 1.0f : std::max(0.0f, x - 1.0f);
  return outcome({{State{next}, 1.0}}, 0.0f);
}

/// From 0: action 1 reaches the paying state 1 with probability 0.8 (else the empty state 2),
/// action 0 with probability 0.2. States 1 and 2 end the episode paying 1 and 0.
StateActionInfo twoArmed(const State& s, int a) {
  if (s[0] == 1.0f) {
    return outcome({{State{0.0f}, 1.0}}, 1.0f, 1.0f);
  }
  if (s[0] == 2.0f) {
    return outcome({{State{0.0f}, 1.0}}, 0.0f, 1.0f);
  }
  const double p = a == 1 ? 0.8 : 0.2;
  return outcome({{State{1.0f}, p}, {State{2.0f}, 1.0 - p}}, 0.0f);
}

UctPlanner::Config config(int actions, double gamma, float maxFeature) {
  UctPlanner::Config c;
  c.numActions = actions;
  c.gamma = gamma;
  c.featMin = {0.0f};
  c.featMax = {maxFeature};
  return c;
}

std::shared_ptr<FunctionView> view(FunctionView::Fn fn) {
  return std::make_shared<FunctionView>(std::move(fn));
}

}  // namespace

TEST(UctPlanner, PicksTheObviousActionOnAChain) {
  UctPlanner planner(config(2, 0.9, 5.0f), 7);
  planner.setModel(view(chain));
  EXPECT_EQ(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(3000)), 3000);
  for (float x = 0.0f; x < 5.0f; x += 1.0f) {
    EXPECT_EQ(planner.bestAction(State{x}), 1) << "state " << x;
  }
  // Right from 4 pays 1 and ends: a deterministic one-step value.
  EXPECT_NEAR(planner.qValues(State{4.0f})[1], 1.0, 0.02);
}

TEST(UctPlanner, PicksTheBetterArmUnderStochasticTransitions) {
  for (double lambda : {0.1, 1.0}) {
    UctPlanner::Config c = config(2, 0.9, 2.0f);
    c.lambda = lambda;
    UctPlanner planner(c, 3);
    planner.setModel(view(twoArmed));
    planner.plan(State{0.0f}, PlanningBudget::ofRollouts(4000));
    EXPECT_EQ(planner.bestAction(State{0.0f}), 1) << "lambda " << lambda;
    const std::vector<double> q = planner.qValues(State{0.0f});
    EXPECT_NEAR(q[1], 0.9 * 0.8, 0.1) << "lambda " << lambda;
    EXPECT_NEAR(q[0], 0.9 * 0.2, 0.1) << "lambda " << lambda;
  }
}

TEST(UctPlanner, OneStepValuesApproachTheirTargets) {
  // Action a pays r[a] and ends, except action 3, which pays 0 and leads to state 1, where any
  // action pays 2 and ends: Q(0,3) = γ·2. With α_k = 10/(k+10) at the k-th update,
  // Q − target = (q0 − target)·Π_k k/(k+10) = (q0 − target)·n!·10!/(n+10)!, q0 ∈ [0, 0.01):
  // a deterministic target is reached to float precision within a few dozen updates.
  const double gamma = 0.9;
  const std::vector<double> r{0.2, 1.0, 0.5};
  auto fn = [&r](const State& s, int a) {
    if (s[0] == 1.0f) {
      return outcome({{State{0.0f}, 1.0}}, 2.0f, 1.0f);
    }
    if (a == 3) {
      return outcome({{State{1.0f}, 1.0}}, 0.0f);
    }
    return outcome({{State{0.0f}, 1.0}}, static_cast<float>(r[a]), 1.0f);
  };
  UctPlanner::Config c = config(4, gamma, 1.0f);
  c.rewardRange = 2.0;
  UctPlanner planner(c, 11);
  planner.setModel(view(fn));
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(4000));
  const std::vector<double> q = planner.qValues(State{0.0f});
  const std::vector<double> targets{0.2, 1.0, 0.5, gamma * 2.0};
  for (int a = 0; a < 4; ++a) {
    const long updates = planner.actionVisits(State{0.0f}, a) - 1;
    ASSERT_GT(updates, 100) << "action " << a;
    EXPECT_NEAR(q[a], targets[a], 1e-6) << "action " << a;
  }
  EXPECT_EQ(planner.bestAction(State{0.0f}), 3);
}

TEST(UctPlanner, LambdaOneBacksUpTheReturnAndLambdaZeroTheMaxQ) {
  // A corridor 0 → 1 → 2 → 3, every action moving right; at 3 any action pays 1 and ends. After
  // one rollout, with c = 10/11 (α at N = 1):
  //   λ = 1: Q(0) = c·γ³ (the discounted return reaches the root),
  //   λ = 0: each state passes up max Q: Q(2) = c·γ·1, Q(1) = c·γ·Q(2), Q(0) = c·γ·Q(1) = c³·γ³,
  // up to the initial values q0 < 0.01, weighted by 1 − c at each level.
  auto corridor = [](const State& s, int) {
    if (s[0] >= 3.0f) {
      return outcome({{State{3.0f}, 1.0}}, 1.0f, 1.0f);
    }
    return outcome({{State{s[0] + 1.0f}, 1.0}}, 0.0f);
  };
  const double gamma = 0.9, c = 10.0 / 11.0;
  for (double lambda : {0.0, 1.0}) {
    UctPlanner::Config cfg = config(2, gamma, 3.0f);
    cfg.lambda = lambda;
    UctPlanner planner(cfg, 5);
    planner.setModel(view(corridor));
    ASSERT_EQ(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(1)), 1);
    const std::vector<double> q = planner.qValues(State{0.0f});
    const double best = *std::max_element(q.begin(), q.end());
    const double expected = lambda == 1.0 ? c * std::pow(gamma, 3) : std::pow(c * gamma, 3);
    EXPECT_NEAR(best, expected, 0.005) << "lambda " << lambda;
  }
}

TEST(UctPlanner, OutOfRangeSuccessorIsReplacedByTheCurrentState) {
  // Both actions leave the declared range [0, 5]: every step stays in state 0. Only the first
  // occurrence of a state on the path updates it, so one rollout adds exactly one visit.
  auto leave = [](const State&, int a) {
    return outcome({{State{a == 0 ? 10.0f : -3.0f}, 1.0}}, 0.5f);
  };
  UctPlanner::Config c = config(2, 0.9, 5.0f);
  c.maxDepth = 5;
  UctPlanner planner(c, 1);
  planner.setModel(view(leave));
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(1));
  EXPECT_EQ(planner.numStates(), 1u);
  EXPECT_TRUE(planner.qValues(State{10.0f}).empty());
  EXPECT_EQ(planner.stateVisits(State{0.0f}), 2);
  EXPECT_EQ(planner.actionVisits(State{0.0f}, 0) + planner.actionVisits(State{0.0f}, 1), 3);

  // Within ε of the bound is in range; NaN is not.
  for (const auto& [next, states] :
       std::vector<std::pair<float, std::size_t>>{{5.000001f, 2}, {5.1f, 1}, {std::nanf(""), 1}}) {
    UctPlanner::Config d = config(1, 0.9, 5.0f);
    d.maxDepth = 1;
    UctPlanner p(d, 1);
    const float n = next;
    p.setModel(view([n](const State&, int) { return outcome({{State{n}, 1.0}}, 0.0f); }));
    p.plan(State{4.0f}, PlanningBudget::ofRollouts(1));
    EXPECT_EQ(p.numStates(), states) << "successor " << next;
  }
}

TEST(UctPlanner, DiscretisationMatchesTheOriginalBinning) {
  // factor = (max − min)/n; bin = int((s ± factor/2)/factor), + for s > 0; ds = factor·bin.
  UctPlanner::Config c;
  c.numActions = 2;
  c.featMin = {0.0f, -1.0f};
  c.featMax = {10.0f, 1.0f};
  c.statesPerDim = {5, 4};  // factors 2 and 0.5
  UctPlanner planner(c, 1);
  const std::vector<std::pair<State, State>> cases{
      {{3.1f, -0.3f}, {4.0f, -0.5f}},   // int(2.05) = 2; int(-1.1) = -1
      {{0.9f, 0.2f}, {0.0f, 0.0f}},     // int(0.95) = 0; int(0.9) = 0
      {{9.9f, 0.0f}, {10.0f, 0.0f}},    // int(5.45) = 5; 0 is not > 0: int(-0.5) = 0
      {{-1.5f, 0.8f}, {-2.0f, 1.0f}},   // int(-1.25) = -1; int(2.1) = 2
      {{5.0f, -0.76f}, {6.0f, -1.0f}},  // int(3) = 3; int(-2.02) = -2
  };
  for (const auto& [s, expected] : cases) {
    const State ds = planner.discretize(s);
    ASSERT_EQ(ds.size(), 2u);
    EXPECT_FLOAT_EQ(ds[0], expected[0]) << s[0];
    EXPECT_FLOAT_EQ(ds[1], expected[1]) << s[1];
  }
  // One entry applies to every feature; 0 leaves a feature continuous.
  c.statesPerDim = {5};
  EXPECT_FLOAT_EQ(UctPlanner(c, 1).discretize({3.1f, 0.3f})[1], 0.4f);  // factor 0.4: int(1.25)
  c.statesPerDim = {0, 4};
  EXPECT_FLOAT_EQ(UctPlanner(c, 1).discretize({3.1f, 0.3f})[0], 3.1f);
}

TEST(UctPlanner, TrackActualCarriesTheContinuousState) {
  // Bins of width 1 on [0, 10]; the model moves +0.25 from the binned state. From 2.0 the
  // binned rollout never leaves bin 2 (2.25 bins to 2); carrying the actual state it reaches
  // 2.5, which bins to 3.
  auto drift = [](const State& s, int) { return outcome({{State{s[0] + 0.25f}, 1.0}}, 0.0f); };
  for (bool track : {false, true}) {
    UctPlanner::Config c = config(1, 0.9, 10.0f);
    c.statesPerDim = {10};
    c.trackActual = track;
    c.maxDepth = 4;
    UctPlanner planner(c, 1);
    planner.setModel(view(drift));
    planner.plan(State{2.0f}, PlanningBudget::ofRollouts(1));
    EXPECT_EQ(planner.numStates(), track ? 2u : 1u) << "trackActual " << track;
    EXPECT_EQ(planner.qValues(State{3.0f}).empty(), !track) << "trackActual " << track;
  }
}

TEST(UctPlanner, CountsAreCappedOnANewModel) {
  auto bandit = [](const State&, int a) {
    return outcome({{State{0.0f}, 1.0}}, 0.3f * static_cast<float>(a), 1.0f);
  };
  const auto model = view(bandit);
  UctPlanner planner(config(3, 0.9, 1.0f), 2);
  planner.setModel(model);
  const State s{0.0f};
  planner.plan(s, PlanningBudget::ofRollouts(500));
  EXPECT_EQ(planner.stateVisits(s), 501);
  long most = 0;
  for (int a = 0; a < 3; ++a) {
    most = std::max(most, planner.actionVisits(s, a));
  }
  EXPECT_GT(most, 10);
  const std::vector<double> q = planner.qValues(s);

  planner.setModel(model);                // a new version, even of the same view
  planner.setModel(model);                // capping twice is capping once
  EXPECT_EQ(planner.stateVisits(s), 30);  // 10·A
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(planner.actionVisits(s, a), 10);
  }
  EXPECT_EQ(planner.qValues(s), q);  // values survive a model change
  planner.plan(s, PlanningBudget::ofRollouts(1));
  EXPECT_EQ(planner.stateVisits(s), 31);
  long sum = 0;
  for (int a = 0; a < 3; ++a) {
    sum += planner.actionVisits(s, a);
  }
  EXPECT_LE(sum, 31);
}

TEST(UctPlanner, SameSeedSameValuesAndActions) {
  auto run = [](std::uint64_t seed) {
    UctPlanner planner(config(2, 0.9, 2.0f), seed);
    planner.setModel(view(twoArmed));
    std::vector<int> actions;
    for (int i = 0; i < 20; ++i) {
      planner.plan(State{0.0f}, PlanningBudget::ofRollouts(25));
      actions.push_back(planner.bestAction(State{0.0f}));
      actions.push_back(planner.bestAction(State{7.0f}));  // unknown state: a random action
    }
    std::vector<double> q = planner.qValues(State{0.0f});
    const std::vector<double> q1 = planner.qValues(State{1.0f});
    q.insert(q.end(), q1.begin(), q1.end());
    return std::make_pair(actions, q);
  };
  const auto a = run(42), b = run(42), c = run(43);
  EXPECT_EQ(a.first, b.first);
  EXPECT_EQ(a.second, b.second);
  EXPECT_NE(a.second, c.second);
}

TEST(UctPlanner, DeterministicAgentLoopIsReproducible) {
  // The deterministic agent: model->update, planner->setModel(model->view()), plan a fixed
  // number of rollouts, act greedily. A tabular model learns the chain as it goes.
  class TabularModel : public rl_common::MDPModel {
   public:
    bool update(const std::vector<Experience>& experiences) override {
      auto next = std::make_shared<Table>(table_ ? *table_ : Table());
      for (const Experience& e : experiences) {
        (*next)[{e.s, e.action}] = e;
      }
      table_ = next;
      return true;
    }
    std::shared_ptr<const rl_common::ModelView> view() const override {
      return std::make_shared<View>(table_);
    }

   private:
    using Table = std::map<std::pair<State, int>, Experience>;
    struct View : rl_common::ModelView {
      explicit View(std::shared_ptr<const Table> t) : table(std::move(t)) {}
      StateActionInfo query(const State& s, int a) const override {
        if (!table || table->count({s, a}) == 0) {
          return outcome({{s, 1.0}}, 1.0f);  // optimistic about the unknown
        }
        const auto it = table->find({s, a});
        const Experience& e = it->second;
        return outcome({{e.next, 1.0}}, e.reward, e.terminal ? 1.0f : 0.0f);
      }
      std::shared_ptr<const Table> table;
    };
    std::shared_ptr<const Table> table_;
  };

  auto episode = [](std::uint64_t seed) {
    TabularModel model;
    UctPlanner planner(config(2, 0.9, 5.0f), seed);
    planner.setModel(model.view());
    std::vector<int> actions;
    State s{0.0f};
    for (int step = 0; step < 40; ++step) {
      planner.plan(s, PlanningBudget::ofRollouts(30));
      const int a = planner.bestAction(s);
      actions.push_back(a);
      const StateActionInfo truth = chain(s, a);
      Experience e{s, a, truth.reward, truth.transitions.front().first, truth.termProb > 0.5f};
      model.update({e});
      planner.setModel(model.view());
      s = e.terminal ? State{0.0f} : e.next;
    }
    return actions;
  };
  const std::vector<int> first = episode(9);
  EXPECT_EQ(first, episode(9));
  EXPECT_GT(std::count(first.begin(), first.end(), 1), 5);  // it does go right
}

TEST(UctPlanner, RolloutBudgetIsExact) {
  UctPlanner planner(config(2, 0.9, 2.0f), 1);
  planner.setModel(view(twoArmed));
  EXPECT_EQ(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(37)), 37);
  EXPECT_EQ(planner.stateVisits(State{0.0f}), 38);  // the root is updated once per rollout
  EXPECT_EQ(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(1)), 1);
  EXPECT_EQ(planner.stateVisits(State{0.0f}), 39);
}

TEST(UctPlanner, DeadlineBudgetStopsPlanning) {
  using Clock = std::chrono::steady_clock;
  UctPlanner planner(config(2, 0.9, 5.0f), 1);
  planner.setModel(view(chain));
  // A deadline already past still runs one rollout.
  EXPECT_EQ(
      planner.plan(State{0.0f}, PlanningBudget::until(Clock::now() - std::chrono::seconds(1))), 1);
  const auto deadline = Clock::now() + std::chrono::milliseconds(30);
  const long done = planner.plan(State{0.0f}, PlanningBudget::until(deadline));
  EXPECT_GE(done, 1);
  EXPECT_GE(Clock::now(), deadline);
  // Whichever limit comes first.
  PlanningBudget both = PlanningBudget::ofRollouts(1000000000L);
  both.deadline = Clock::now() + std::chrono::milliseconds(20);
  EXPECT_LT(planner.plan(State{0.0f}, both), 1000000000L);
  both.deadline = Clock::now() + std::chrono::hours(1);
  both.rollouts = 5;
  EXPECT_EQ(planner.plan(State{0.0f}, both), 5);
}

TEST(UctPlanner, RejectsBadUse) {
  UctPlanner planner(config(2, 0.9, 5.0f), 1);
  EXPECT_THROW(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(1)), std::runtime_error);
  EXPECT_THROW(planner.setModel(nullptr), std::invalid_argument);
  planner.setModel(view(chain));
  EXPECT_THROW(planner.plan(State{0.0f}, PlanningBudget()), std::invalid_argument);
  EXPECT_THROW(planner.plan(State{0.0f, 1.0f}, PlanningBudget::ofRollouts(1)),
               std::invalid_argument);
  EXPECT_THROW(planner.plan(State{std::nanf("")}, PlanningBudget::ofRollouts(1)),
               std::invalid_argument);

  auto bad = [](auto edit) {
    UctPlanner::Config c = config(2, 0.9, 5.0f);
    edit(c);
    return c;
  };
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.numActions = 0; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.gamma = 1.0; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.lambda = 1.5; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.maxDepth = 0; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.featMax = {}; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.statesPerDim = {3, 3}; }), 1), std::invalid_argument);
  EXPECT_THROW(UctPlanner(bad([](auto& c) { c.history = -1; }), 1), std::invalid_argument);
  try {
    UctPlanner(bad([](auto& c) { c.gamma = 1.0; }), 1);
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("UctPlanner::UctPlanner(): gamma"), std::string::npos);
  }
}

TEST(UctPlanner, HistoryIsPartOfTheModelInputAndTheKey) {
  // k = 2 past actions of A = 2, one-hot and oldest first, after the state.
  UctPlanner::Config c = config(2, 0.9, 10.0f);
  c.history = 2;
  c.maxDepth = 3;
  UctPlanner planner(c, 1);
  const auto model = view([](const State& in, int) {
    return outcome({{State{in[0] + 1.0f}, 1.0}}, 0.0f);
  });
  planner.setModel(model);
  planner.setActionHistory({1});
  EXPECT_EQ(planner.actionHistory(), (std::vector<int>{-1, 1}));
  EXPECT_EQ(planner.modelInput(State{3.0f}), (State{3.0f, 0, 0, 0, 1}));

  planner.plan(State{3.0f}, PlanningBudget::ofRollouts(1));
  const auto inputs = model->inputs();
  ASSERT_EQ(inputs.size(), 3u);  // three steps, three distinct (input, action) pairs
  EXPECT_EQ(inputs[0].first, (State{3.0f, 0, 0, 0, 1}));
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    const State& prev = inputs[i - 1].first;
    const State& in = inputs[i].first;
    ASSERT_EQ(in.size(), 5u);
    EXPECT_EQ(in[0], prev[0] + 1.0f);
    EXPECT_EQ(in[1], prev[3]);  // the newest action became the oldest
    EXPECT_EQ(in[2], prev[4]);
    State code{0.0f, 0.0f};
    code[inputs[i - 1].second] = 1.0f;
    EXPECT_EQ(in[3], code[0]);  // the action just taken is the newest
    EXPECT_EQ(in[4], code[1]);
  }

  EXPECT_FALSE(planner.qValues(State{3.0f}).empty());
  planner.setActionHistory({0, 0});
  EXPECT_TRUE(planner.qValues(State{3.0f}).empty());  // another history, another record
  EXPECT_THROW(planner.setActionHistory({0, 1, 0}), std::invalid_argument);
  EXPECT_THROW(planner.setActionHistory({2}), std::invalid_argument);
}

TEST(UctPlanner, ModelPredictionsAreCachedPerModelVersion) {
  const auto model = view(chain);
  UctPlanner planner(config(2, 0.9, 5.0f), 4);
  planner.setModel(model);
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(500));
  const long first = model->queries();
  EXPECT_LE(first, 10);  // states 0..4, two actions each
  EXPECT_EQ(planner.numCachedPredictions(), static_cast<std::size_t>(first));
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(100));
  EXPECT_EQ(model->queries(), first);  // nothing new to ask
  planner.setModel(model);
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(500));
  EXPECT_GT(model->queries(), first);  // refreshed after the version change
  EXPECT_LE(model->queries(), 2 * first);
}

TEST(UctPlanner, CachesAndStateTableAreBounded) {
  // Two continuous features drifting at random: a new state at nearly every step.
  auto drift = [](const State& s, int a) {
    const float d = 0.001f * static_cast<float>(a + 1);
    return outcome({{State{s[0] + d, s[1]}, 0.5}, {State{s[0], s[1] + d}, 0.5}}, 0.0f);
  };
  UctPlanner::Config c;
  c.numActions = 2;
  c.maxDepth = 50;
  c.maxStates = 500;
  c.maxCachedPredictions = 64;
  UctPlanner planner(c, 8);
  planner.setModel(view(drift));
  for (int i = 0; i < 20; ++i) {
    planner.plan(State{0.0f, 0.0f}, PlanningBudget::ofRollouts(20));
    EXPECT_LE(planner.numStates(), c.maxStates);
    EXPECT_LE(planner.numCachedPredictions(), 2 * planner.numStates());
    EXPECT_LE(planner.numCachedPredictions(), c.maxCachedPredictions);
  }
  EXPECT_GT(planner.stateVisits(State{0.0f, 0.0f}), 400);  // the root survives pruning
  const int a = planner.bestAction(State{0.0f, 0.0f});
  EXPECT_TRUE(a == 0 || a == 1);
}

TEST(UctPlanner, LeastRecentlyVisitedStatesAreEvictedFirst) {
  UctPlanner::Config c = config(2, 0.9, 5.0f);
  c.maxDepth = 1;  // each rollout touches the root and at most one successor
  c.maxStates = 3;
  UctPlanner planner(c, 6);
  planner.setModel(view(chain));
  for (float root : {0.0f, 2.0f, 4.0f}) {
    planner.plan(State{root}, PlanningBudget::ofRollouts(1));
    EXPECT_LE(planner.numStates(), 3u);
  }
  EXPECT_TRUE(planner.qValues(State{0.0f}).empty());  // the oldest root went first
  EXPECT_FALSE(planner.qValues(State{4.0f}).empty());
  // Planning on from a kept state still works, and the table stays bounded.
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(200));
  EXPECT_LE(planner.numStates(), 3u);
  EXPECT_EQ(planner.stateVisits(State{0.0f}), 201);
}

TEST(UctPlanner, ARepeatedStateOnARolloutTriesAnotherAction) {
  // A corridor where action 0 stays put (a self-loop, like PICKUP off the key) and action 1
  // steps right; nothing pays. The first choice at each state is a coin flip (equal counts).
  // Counting the path's choices, a state met again takes the other action, so one rollout of
  // 200 steps walks about 130 states down the corridor. Counting only on return (the
  // original), the state repeats its choice: the first self-loop holds the rollout to the
  // depth cap, and rollouts end within a few states of the start.
  auto corridor = [](const State& s, int a) {
    return outcome({{State{a == 1 ? s[0] + 1.0f : s[0]}, 1.0}}, 0.0f);
  };
  for (bool countPath : {true, false}) {
    UctPlanner::Config c = config(2, 0.99, 1000.0f);
    c.countPathVisits = countPath;
    UctPlanner planner(c, 5);
    const auto model = view(corridor);
    planner.setModel(model);
    planner.plan(State{0.0f}, PlanningBudget::ofRollouts(10));
    float furthest = 0.0f;
    for (const auto& [input, action] : model->inputs()) furthest = std::max(furthest, input[0]);
    if (countPath) {
      EXPECT_GE(furthest, 60.0f);
    } else {
      EXPECT_LT(furthest, 30.0f);  // P(a rollout gets 30 states along) = 2^-30
    }
  }
}

TEST(UctPlanner, NormalizedBoundFollowsSmallRewardsTheRangeBoundDoesNot) {
  // One state, three actions, each ending the episode: action 2 pays 0.02, the others 0.01 (the
  // scale of VANIR's bonuses) in a task whose external range is 10. The Range bound's constant,
  // 2·10/(1−γ) = 2000, dwarfs the 0.01 difference: visits stay almost uniform. The Normalized
  // bound weighs Q by the state's own Q range and gives the better action most of the visits.
  auto fn = [](const State&, int a) {
    return outcome({{State{0.0f}, 1.0}}, a == 2 ? 0.02f : 0.01f, 1.0f);
  };
  for (auto bound : {UctPlanner::UcbBound::Range, UctPlanner::UcbBound::Normalized}) {
    UctPlanner::Config c = config(3, 0.99, 1.0f);
    c.rewardRange = 10.0;
    c.ucbBound = bound;
    c.ucbC = 0.5;
    UctPlanner planner(c, 13);
    planner.setModel(view(fn));
    planner.plan(State{0.0f}, PlanningBudget::ofRollouts(600));
    const double best = static_cast<double>(planner.actionVisits(State{0.0f}, 2));
    const double other = static_cast<double>(planner.actionVisits(State{0.0f}, 0));
    if (bound == UctPlanner::UcbBound::Range) {
      EXPECT_LT(best / other, 1.2);
    } else {
      EXPECT_GT(best / other, 4.0);
    }
    EXPECT_EQ(planner.bestAction(State{0.0f}), 2);
  }
  UctPlanner::Config bad = config(3, 0.99, 1.0f);
  bad.ucbC = -1.0;
  EXPECT_THROW(UctPlanner(bad, 1), std::invalid_argument);
}

TEST(UctPlanner, BonusOncePerPathStopsASelfLoopFromCollectingItsBonusAgain) {
  // From state 0, action 0 is a self-loop whose prediction carries an intrinsic bonus of 1 (as
  // PICKUP off the key when the trees disagree); action 1 ends the episode and pays 0. With
  // λ 1, γ 0.5 and depth 3 the only rollouts are [0,0,0 | cap] (and ones ending on action 1).
  // Collected on every repeat, looping returns 1 + .5 + .25 + .125·maxQ: Q(0, 0) → 2 (the
  // fixed point of Q = 1.75 + .125·Q); collected once, it returns 1 + .125·maxQ: Q → 8/7.
  auto fn = [](const State&, int a) {
    if (a == 1) return outcome({{State{0.0f}, 1.0}}, 0.0f, 1.0f);
    StateActionInfo info = outcome({{State{0.0f}, 1.0}}, 1.0f);
    info.varianceReward = 1.0f;
    return info;
  };
  for (bool once : {false, true}) {
    UctPlanner::Config c = config(2, 0.5, 1.0f);
    c.lambda = 1.0;
    c.maxDepth = 3;
    c.bonusOncePerPath = once;
    UctPlanner planner(c, 17);
    planner.setModel(view(fn));
    planner.plan(State{0.0f}, PlanningBudget::ofRollouts(3000));
    EXPECT_NEAR(planner.qValues(State{0.0f})[0], once ? 8.0 / 7.0 : 2.0, 1e-3) << once;
  }
}

TEST(UctPlanner, SetUcbBoundSwitchesTheBoundForLaterRollouts) {
  // The first problem of NormalizedBoundFollowsSmallRewards...: planned under the Range bound,
  // then switched to Normalized, the later rollouts go mostly to the better action.
  auto fn = [](const State&, int a) {
    return outcome({{State{0.0f}, 1.0}}, a == 2 ? 0.02f : 0.01f, 1.0f);
  };
  UctPlanner::Config c = config(3, 0.99, 1.0f);
  c.rewardRange = 10.0;
  UctPlanner planner(c, 13);
  planner.setModel(view(fn));
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(300));
  const long best0 = planner.actionVisits(State{0.0f}, 2);
  const long other0 = planner.actionVisits(State{0.0f}, 0);
  EXPECT_LT(std::abs(best0 - other0), 30);
  planner.setUcbBound(UctPlanner::UcbBound::Normalized, 0.5);
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(600));
  const long best = planner.actionVisits(State{0.0f}, 2) - best0;
  const long other = planner.actionVisits(State{0.0f}, 0) - other0;
  EXPECT_GT(best, 4 * other);
  EXPECT_THROW(planner.setUcbBound(UctPlanner::UcbBound::Normalized, -0.1), std::invalid_argument);
}

TEST(UctPlanner, MinOutcomeProbabilityDropsImplausibleFeatureValues) {
  // From 0 every action leads to 1 with probability 0.95 and to 5 with 0.05 (a value one tree
  // of a forest predicts); every other state stays put. Without the cut, 200 rollouts meet
  // state 5 (P(never) = 0.95^200 < 1e-4); with a cut of 0.1 they never do.
  auto fn = [](const State& s, int) {
    StateActionInfo info;
    info.known = true;
    if (s[0] == 0.0f) {
      info.factored = {{{1.0f, 0.95}, {5.0f, 0.05}}};
    } else {
      info.factored = {{{s[0], 1.0}}};
    }
    return info;
  };
  for (double cut : {0.0, 0.1}) {
    UctPlanner::Config c = config(2, 0.9, 5.0f);
    c.maxDepth = 3;
    c.minOutcomeProbability = cut;
    UctPlanner planner(c, 23);
    const auto model = view(fn);
    planner.setModel(model);
    planner.plan(State{0.0f}, PlanningBudget::ofRollouts(200));
    bool metFive = false;
    for (const auto& [input, action] : model->inputs()) metFive = metFive || input[0] == 5.0f;
    EXPECT_EQ(metFive, cut == 0.0) << "cut " << cut;
  }
  // All values below the cut: the most likely one is taken.
  auto flat = [](const State& s, int) {
    StateActionInfo info;
    info.known = true;
    info.factored = {{{s[0] == 0.0f ? 2.0f : s[0], 0.6}, {3.0f, 0.4}}};
    if (s[0] != 0.0f) info.factored = {{{s[0], 1.0}}};
    return info;
  };
  UctPlanner::Config c = config(1, 0.9, 5.0f);
  c.maxDepth = 2;
  c.minOutcomeProbability = 0.9;
  UctPlanner planner(c, 29);
  const auto model = view(flat);
  planner.setModel(model);
  planner.plan(State{0.0f}, PlanningBudget::ofRollouts(50));
  for (const auto& [input, action] : model->inputs()) EXPECT_NE(input[0], 3.0f);
  UctPlanner::Config bad = config(1, 0.9, 5.0f);
  bad.minOutcomeProbability = 1.5;
  EXPECT_THROW(UctPlanner(bad, 1), std::invalid_argument);
}

TEST(UctPlanner, AStopRequestEndsAStepAtTheNextRollout) {
  // A SIGINT handler calls rl_common::requestStop(): a step of 100 million rollouts (minutes
  // here) ends within a rollout of it.
  UctPlanner planner(config(2, 0.9, 5.0f), 7);
  planner.setModel(view(chain));
  rl_common::clearStopRequest();
  std::thread stopper([] {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    rl_common::requestStop();
  });
  const auto start = std::chrono::steady_clock::now();
  const long done = planner.plan(State{0.0f}, PlanningBudget::ofRollouts(100000000));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  stopper.join();
  rl_common::clearStopRequest();
  EXPECT_GT(done, 0);
  EXPECT_LT(done, 100000000);
  EXPECT_LT(seconds, 5.0);
  // Cleared, the next step plans its whole budget again.
  EXPECT_EQ(planner.plan(State{0.0f}, PlanningBudget::ofRollouts(500)), 500);
}
