// Value iteration, policy iteration and prioritized sweeping on a small MDP with known values.
#include <gtest/gtest.h>

#include "rl_agent/planner/policy_iteration.h"
#include "rl_agent/planner/prioritized_sweeping.h"
#include "rl_agent/planner/value_iteration.h"
#include "small_mdps.h"

using namespace rl_agent;
using rl_common::State;

namespace {

StateSpacePlanner::Config config(double tolerance = 1e-8) {
  StateSpacePlanner::Config c;
  c.numActions = 2;
  c.gamma = 0.9;
  c.tolerance = tolerance;
  c.maxSteps = 10;
  return c;
}

template <class P>
void expectChainValues(P& planner, double tol) {
  planner.setModel(test_mdps::chainModel());
  planner.plan(State{0}, rl_common::PlanningBudget{});
  planner.plan(State{2}, rl_common::PlanningBudget{});
  const auto qa = planner.qValues(State{0});
  const auto qb = planner.qValues(State{1});
  const auto qc = planner.qValues(State{2});
  ASSERT_EQ(qa.size(), 2u);
  ASSERT_EQ(qb.size(), 2u);
  EXPECT_NEAR(qb[0], test_mdps::kChainVB, tol);
  EXPECT_NEAR(qa[1], test_mdps::kChainVA, tol);
  EXPECT_NEAR(qa[0], 0.9 * test_mdps::kChainVA, tol);
  EXPECT_NEAR(qb[1], 0.9 * test_mdps::kChainVA, tol);
  EXPECT_NEAR(qc[0], 5.0, tol);  // terminal: no bootstrap
  EXPECT_EQ(planner.bestAction(State{0}), 1);
  EXPECT_EQ(planner.bestAction(State{1}), 0);
}

}  // namespace

TEST(ValueIteration, ConvergesToHandComputedValues) {
  ValueIteration vi(config(), 1);
  expectChainValues(vi, 1e-5);
  EXPECT_GT(vi.lastSweeps(), 1);
}

TEST(PolicyIteration, ConvergesToHandComputedValues) {
  PolicyIteration pi(config(), 1);
  expectChainValues(pi, 1e-5);
}

TEST(PrioritizedSweeping, ConvergesCloseToValueIteration) {
  // Threshold 1e-4: values within about 1e-4 / (1 − γ) = 1e-3.
  PrioritizedSweeping ps(config(1e-4), 1);
  expectChainValues(ps, 2e-3);
}

TEST(ValueIteration, BudgetLimitsSweepsAndWarmStartContinues) {
  ValueIteration vi(config(), 1);
  vi.setModel(test_mdps::chainModel());
  EXPECT_EQ(vi.plan(State{0}, rl_common::PlanningBudget::ofRollouts(1)), 1);
  // One sweep: B's self-loop is solved exactly (1 / (1 − 0.9); a plain backup gives 1), but A,
  // swept before B, has not seen it yet.
  EXPECT_NEAR(vi.value(State{1}), 10.0, 1e-9);
  EXPECT_LT(vi.value(State{0}), 1.0);
  vi.plan(State{0}, rl_common::PlanningBudget{});
  EXPECT_NEAR(vi.value(State{0}), test_mdps::kChainVA, 1e-9);
  // Converged and nothing changed: no more work.
  EXPECT_EQ(vi.plan(State{0}, rl_common::PlanningBudget{}), 0);
}

TEST(ValueIteration, ExpandsOnlyWithinMaxSteps) {
  // A chain 0 -> 1 -> 2 -> ... ; with maxSteps 2 only states 0, 1, 2 get predictions.
  auto m = std::make_shared<test_mdps::TableModelView>();
  for (int i = 0; i < 10; ++i) {
    m->set(State{float(i)}, 0, {{State{float(i + 1)}, 1.0}}, 1.0f);
    m->set(State{float(i)}, 1, {{State{float(i)}, 1.0}}, 0.0f);
  }
  auto c = config();
  c.maxSteps = 2;
  ValueIteration vi(c, 1);
  vi.setModel(m);
  vi.plan(State{0}, rl_common::PlanningBudget{});
  EXPECT_EQ(vi.numExpanded(), 3u);
  // State 3 is unexpanded (Q = 0): Q(2, a0) = 1, Q(1, a0) = 1.9, Q(0, a0) = 2.71.
  EXPECT_NEAR(vi.value(State{0}), 2.71, 1e-6);
  EXPECT_THROW(ValueIteration(StateSpacePlanner::Config{}, 1), std::invalid_argument);
}

TEST(StateSpacePlanner, UnknownStateGivesRandomActionAndNoModelThrows) {
  ValueIteration vi(config(), 1);
  EXPECT_THROW(vi.plan(State{0}, rl_common::PlanningBudget{}), std::runtime_error);
  const int a = vi.bestAction(State{42});
  EXPECT_TRUE(a == 0 || a == 1);
  EXPECT_TRUE(vi.qValues(State{42}).empty());
}

TEST(StateSpacePlanner, SuccessorsOutsideTheRangesStayPut) {
  // A: a0 reaches B or an out-of-range state {9} (p 0.5 each); a1 stays. B pays 1 forever.
  // {9} is not real (the model is never asked about it): its half stays in A, so
  // V(A) = 0.9 (0.5 V(A) + 0.5 V(B)), V(B) = 10, V(A) = 4.5 / 0.55.
  auto m = std::make_shared<test_mdps::TableModelView>();
  m->set(State{0}, 0, {{State{9}, 0.5}, {State{1}, 0.5}}, 0.0f);
  m->set(State{0}, 1, {{State{0}, 1.0}}, 0.0f);
  m->set(State{1}, 0, {{State{1}, 1.0}}, 1.0f);
  m->set(State{1}, 1, {{State{1}, 1.0}}, 1.0f);
  auto c = config();
  c.featMin = {0.0f};
  c.featMax = {2.0f};
  ValueIteration vi(c, 1);
  vi.setModel(m);
  vi.plan(State{0}, rl_common::PlanningBudget{});
  EXPECT_EQ(vi.numStates(), 2u);
  EXPECT_NEAR(vi.value(State{1}), 10.0, 1e-5);
  EXPECT_NEAR(vi.value(State{0}), 4.5 / 0.55, 1e-5);
  c.featMax = {1.0f, 2.0f};
  EXPECT_THROW(ValueIteration(c, 1), std::invalid_argument);
}

TEST(StateSpacePlanner, KeyFeaturesShareOneEntryQueriedAtItsRepresentative) {
  // States (x, noise); only x tells table states apart. The model knows only the states it
  // is asked about: (0,0), and (1,7), the first state met with x = 1, whose a0 leads to
  // (1,3): the same entry, so a self-loop paying 1 (V = 10).
  auto m = std::make_shared<test_mdps::TableModelView>();
  m->set(State{0, 0}, 0, {{State{1, 7}, 1.0}}, 0.0f);
  m->set(State{0, 0}, 1, {{State{0, 0}, 1.0}}, 0.0f);
  m->set(State{1, 7}, 0, {{State{1, 3}, 1.0}}, 1.0f);
  m->set(State{1, 7}, 1, {{State{0, 5}, 1.0}}, 0.0f);
  auto c = config();
  c.keyFeatures = {0};
  ValueIteration vi(c, 1);
  vi.setModel(m);
  vi.plan(State{0, 0}, rl_common::PlanningBudget{});
  EXPECT_EQ(vi.numStates(), 2u);
  EXPECT_NEAR(vi.value(State{1, 99}), 10.0, 1e-5);  // looked up by x alone
  EXPECT_NEAR(vi.value(State{0, 0}), 9.0, 1e-5);
  EXPECT_EQ(vi.bestAction(State{0, 42}), 0);
  // A root is its own representative: planning from (1,3) re-queries x = 1 there.
  m->set(State{1, 3}, 0, {{State{1, 3}, 1.0}}, 2.0f);
  m->set(State{1, 3}, 1, {{State{0, 0}, 1.0}}, 0.0f);
  vi.plan(State{1, 3}, rl_common::PlanningBudget{});
  EXPECT_NEAR(vi.value(State{1, 7}), 20.0, 1e-5);
  EXPECT_EQ(vi.expandedStates(), (std::vector<State>{State{0}, State{1}}));
  c.keyFeatures = {2};
  ValueIteration bad(c, 1);
  bad.setModel(m);
  EXPECT_THROW(bad.plan(State{0, 0}, rl_common::PlanningBudget{}), std::invalid_argument);
}

namespace {

/// A factored prediction: per feature, its values with their probabilities.
rl_common::StateActionInfo factored(std::vector<rl_common::FeatureDistribution> features,
                                    float reward) {
  rl_common::StateActionInfo info;
  info.factored = std::move(features);
  info.reward = reward;
  info.known = true;
  return info;
}

}  // namespace

TEST(StateSpacePlanner, KeyOutcomesReachAnEntryThatEveryFullStateMisses) {
  // States (door, s1, s2, s3), key = door. In (0,0,0,0) a0 opens the door with p 0.5 and,
  // guessed separately, each sensor reads 10 with p 0.5; a1 does nothing. The open door pays 1
  // forever. Over full states every door-open outcome has p 0.5^4 < 0.1: dropped, only the
  // start is kept, V = 0. Over the key, the open door has p 0.5 (sensors at their first most
  // likely value, 0): V(open) = 10, V(start) = 0.9 (0.5 V(start) + 5) = 4.5 / 0.55.
  auto m = std::make_shared<test_mdps::TableModelView>();
  const rl_common::FeatureDistribution coin0{{0.0f, 0.5}, {1.0f, 0.5}};
  const rl_common::FeatureDistribution sensor{{0.0f, 0.5}, {10.0f, 0.5}};
  const rl_common::FeatureDistribution zero{{0.0f, 1.0}}, one{{1.0f, 1.0}};
  m->table[{State{0, 0, 0, 0}, 0}] = factored({coin0, sensor, sensor, sensor}, 0.0f);
  m->table[{State{0, 0, 0, 0}, 1}] = factored({zero, zero, zero, zero}, 0.0f);
  for (int a : {0, 1}) m->table[{State{1, 0, 0, 0}, a}] = factored({one, zero, zero, zero}, 1.0f);
  auto c = config();
  c.keyFeatures = {0};
  c.minTransitionProbability = 0.1;
  ValueIteration joint(c, 1);
  joint.setModel(m);
  joint.plan(State{0, 0, 0, 0}, rl_common::PlanningBudget{});
  EXPECT_EQ(joint.numStates(), 1u);
  EXPECT_NEAR(joint.value(State{0, 0, 0, 0}), 0.0, 1e-9);
  c.keyMarginal = true;
  ValueIteration keyed(c, 1);
  keyed.setModel(m);
  keyed.plan(State{0, 0, 0, 0}, rl_common::PlanningBudget{});
  EXPECT_EQ(keyed.numStates(), 2u);
  EXPECT_NEAR(keyed.value(State{1, 5, 5, 5}), 10.0, 1e-5);
  EXPECT_NEAR(keyed.value(State{0, 0, 0, 0}), 4.5 / 0.55, 1e-5);
  EXPECT_EQ(keyed.bestAction(State{0, 0, 0, 0}), 0);
  // Without key features keyMarginal changes nothing: the same table as over full states.
  c.keyFeatures.clear();
  ValueIteration all(c, 1);
  all.setModel(m);
  all.plan(State{0, 0, 0, 0}, rl_common::PlanningBudget{});
  EXPECT_EQ(all.numStates(), 1u);
}

TEST(ValueIteration, WarmStartFromAnotherTableConvergesInFewerSweeps) {
  ValueIteration cold(config(), 1);
  cold.setModel(test_mdps::chainModel());
  cold.plan(State{0}, rl_common::PlanningBudget{});
  ValueIteration warm(config(), 1);
  warm.warmStartFrom(&cold);
  warm.setModel(test_mdps::chainModel());
  warm.plan(State{0}, rl_common::PlanningBudget{});
  EXPECT_NEAR(warm.value(State{0}), cold.value(State{0}), 1e-6);
  EXPECT_NEAR(warm.value(State{1}), 10.0, 1e-5);
  EXPECT_GE(cold.lastSweeps(), 3);  // B, then A from B, then one to confirm
  EXPECT_EQ(warm.lastSweeps(), 1);  // one sweep confirms the values it was given
}
