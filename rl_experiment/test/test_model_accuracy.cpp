#include "rl_experiment/eval/model_accuracy.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "rl_agent/model/factored_model.h"
#include "rl_common/random.h"

namespace {

using rl_experiment::StateDistribution;
using rl_experiment::variationalDistance;

// A one-feature chain 0..4: action 0 moves +1 with probability 0.8 (else stays), action 1
// stays.
class Chain : public rl_common::TrueModel {
 public:
  std::vector<rl_common::Outcome> transitions(const rl_common::State& s, int a) const override {
    if (a == 1 || s[0] >= 4) return {{s, 0, false, 1.0}};
    return {{{s[0] + 1}, 0, false, 0.8}, {s, 0, false, 0.2}};
  }
  std::vector<rl_common::State> reachableStates() const override {
    return {{0}, {1}, {2}, {3}, {4}};
  }
  void setState(const rl_common::State&) override {}
};

// A model view that always predicts "stay".
class Stay : public rl_common::ModelView {
 public:
  rl_common::StateActionInfo query(const rl_common::State& s, int) const override {
    rl_common::StateActionInfo i;
    i.transitions = {{s, 1.0}};
    i.known = true;
    return i;
  }
};

// A model view that knows the chain exactly, in factored form.
class Exact : public rl_common::ModelView {
 public:
  explicit Exact(const Chain& c) : c_(c) {}
  rl_common::StateActionInfo query(const rl_common::State& s, int a) const override {
    rl_common::StateActionInfo i;
    i.factored.resize(1);
    for (const auto& o : c_.transitions(s, a)) i.factored[0].emplace_back(o.next[0], o.probability);
    i.known = true;
    return i;
  }

 private:
  const Chain& c_;
};

}  // namespace

TEST(VariationalDistance, HandComputedCases) {
  const StateDistribution a = {{{1, 0}, 1.0}};
  const StateDistribution b = {{{2, 0}, 1.0}};
  const StateDistribution half = {{{1, 0}, 0.5}, {{2, 0}, 0.5}};
  EXPECT_DOUBLE_EQ(variationalDistance(a, a), 0.0);
  EXPECT_DOUBLE_EQ(variationalDistance(a, b), 1.0);
  EXPECT_DOUBLE_EQ(variationalDistance(a, half), 0.5);
  EXPECT_DOUBLE_EQ(variationalDistance(half, a), 0.5);
  // Equal states listed twice are merged: {x:.3, x:.2, y:.5} equals half.
  const StateDistribution split = {{{1, 0}, 0.3}, {{2, 0}, 0.5}, {{1, 0}, 0.2}};
  EXPECT_NEAR(variationalDistance(split, half), 0.0, 1e-12);
  // 0.9/0.1 vs 0.6/0.4: 1/2 (0.3 + 0.3).
  const StateDistribution p = {{{0}, 0.9}, {{1}, 0.1}};
  const StateDistribution q = {{{0}, 0.6}, {{1}, 0.4}};
  EXPECT_NEAR(variationalDistance(p, q), 0.3, 1e-12);
}

TEST(VariationalDistance, FactoredPredictionEqualsItsExpansion) {
  // Two features, independent: f0 in {0: .7, 1: .3}, f1 in {5: .5, 6: .5}.
  rl_common::StateActionInfo q;
  q.factored = {{{0.0f, 0.7}, {1.0f, 0.3}}, {{5.0f, 0.5}, {6.0f, 0.5}}};
  q.known = true;
  const StateDistribution truth = {{{0, 5}, 0.6}, {{1, 6}, 0.4}};
  const StateDistribution expanded = {
      {{0, 5}, 0.35}, {{0, 6}, 0.35}, {{1, 5}, 0.15}, {{1, 6}, 0.15}};
  // |.6-.35| + |.4-.15| + .35 + .15 = 1.0 -> 0.5
  EXPECT_NEAR(variationalDistance(truth, expanded), 0.5, 1e-12);
  EXPECT_NEAR(variationalDistance(truth, q), 0.5, 1e-12);
}

TEST(ModelAccuracy, PerfectModelScoresZeroAndStayModelTheExpectedMean) {
  Chain chain;
  rl_experiment::ModelAccuracy acc(chain, 2);
  EXPECT_EQ(acc.numReachableStates(), 5u);
  rl_common::Random rng(7);
  EXPECT_NEAR(acc.evaluate(Exact(chain), rng, 2000), 0.0, 1e-12);
  // "Stay" is wrong only for action 0 in states 0..3, by TV 0.8: mean = 0.8 * (4/5) * (1/2).
  rl_common::Random rng2(7);
  EXPECT_NEAR(acc.evaluate(Stay(), rng2, 20000), 0.32, 0.02);
  EXPECT_THROW(acc.evaluate(Stay(), rng2, 0), std::invalid_argument);
}

TEST(MarginalDistance, EachFeatureAgainstItsOwnMarginal) {
  rl_common::StateActionInfo q;
  q.factored = {{{0.0f, 0.7}, {1.0f, 0.3}}, {{5.0f, 0.5}, {6.0f, 0.5}}};
  q.known = true;
  const StateDistribution truth = {{{0, 5}, 0.6}, {{1, 6}, 0.4}};
  // f0: P = {0: .6, 1: .4}, Q = {0: .7, 1: .3} -> 0.1; f1: P = {5: .6, 6: .4} vs .5/.5 -> 0.1.
  EXPECT_NEAR(rl_experiment::marginalDistance(truth, q, 0), 0.1, 1e-12);
  EXPECT_NEAR(rl_experiment::marginalDistance(truth, q, 1), 0.1, 1e-12);
  EXPECT_THROW(rl_experiment::marginalDistance(truth, q, 2), std::invalid_argument);
  // A listed prediction gives the same marginals as its factored form.
  rl_common::StateActionInfo listed;
  listed.transitions = {{{0, 5}, 0.35}, {{0, 6}, 0.35}, {{1, 5}, 0.15}, {{1, 6}, 0.15}};
  listed.known = true;
  EXPECT_NEAR(rl_experiment::marginalDistance(truth, listed, 0), 0.1, 1e-12);
  EXPECT_NEAR(rl_experiment::marginalDistance(truth, listed, 1), 0.1, 1e-12);
}

TEST(ModelAccuracy, DetailedReportMatchesTheJointAndLocatesTheError) {
  Chain chain;
  rl_experiment::ModelAccuracy acc(chain, 2);
  rl_common::Random rng(7), rng2(7);
  const double joint = acc.evaluate(Stay(), rng, 5000);
  const auto report = acc.evaluateDetailed(Stay(), rng2, 5000);
  EXPECT_DOUBLE_EQ(report.joint, joint);  // the same draws
  ASSERT_EQ(report.perAction.size(), 2u);
  ASSERT_EQ(report.marginal.size(), 1u);
  // "Stay" errs only on action 0 (TV 0.8 in 4 of 5 states): 0.64 there, 0 for action 1.
  EXPECT_NEAR(report.perAction[0], 0.64, 0.03);
  EXPECT_NEAR(report.perAction[1], 0.0, 1e-12);
  // One feature: its marginal is the joint.
  EXPECT_NEAR(report.marginal[0], report.joint, 1e-12);
}

TEST(ModelAccuracy, GroupsSplitTheJointByFeatureValues) {
  Chain chain;
  rl_experiment::ModelAccuracy acc(chain, 2);
  rl_common::Random rng(3);
  const auto report = acc.evaluateDetailed(Stay(), rng, 20000, {0});
  ASSERT_EQ(report.groups.size(), 5u);
  int total = 0;
  double sum = 0.0;
  for (const auto& [name, g] : report.groups) {
    total += g.second;
    sum += g.first;
    // "Stay" errs by 0.8 on action 0 in states 0..3 (half the samples): 0.4; state 4 is exact.
    EXPECT_NEAR(g.first / g.second, name == "f0=4" ? 0.0 : 0.4, 0.03) << name;
  }
  EXPECT_EQ(total, 20000);
  EXPECT_NEAR(sum / total, report.joint, 1e-9);
  EXPECT_TRUE(report.groups.count("f0=2"));
  rl_common::Random rng2(3);
  EXPECT_THROW(acc.evaluateDetailed(Stay(), rng2, 10, {1}), std::invalid_argument);
}

// The accuracy keeps each state-action's prediction between measurements and refreshes it;
// every figure must be the one a new evaluator (a query per sample) gives, as the model learns.
TEST(ModelAccuracy, KeptPredictionsGiveTheFiguresOfANewEvaluator) {
  const Chain chain;
  rl_agent::FactoredModel::Config config;
  config.numActions = 2;
  config.featMin = {0.0f};
  config.featMax = {4.0f};
  config.episodic = false;
  rl_agent::FactoredModel model(config, 5);
  rl_experiment::ModelAccuracy kept(chain, 2);
  rl_common::Random walk(8), keptRng(3), freshRng(3);
  float x = 0.0f;
  int measured = 0;
  for (int t = 0; t < 120; ++t) {
    const int a = walk.uniformInt(0, 1);
    const float next = a == 0 && x < 4.0f && walk.uniform() < 0.8 ? x + 1.0f : x;
    model.update({{{x}, a, 0.0f, {next}, false}});
    x = next == 4.0f ? 0.0f : next;
    if (t % 10 != 9) continue;
    // A measurement of another model in between must not disturb the kept predictions.
    const Stay stay;
    rl_common::Random other(1);
    kept.evaluate(stay, other, 20);
    rl_experiment::ModelAccuracy fresh(chain, 2);
    const auto view = model.factoredView();
    const auto k = kept.evaluateDetailed(*view, keptRng, 50);
    const auto f = fresh.evaluateDetailed(*view, freshRng, 50);
    ASSERT_EQ(k.joint, f.joint) << "t " << t;
    ASSERT_EQ(k.marginal, f.marginal) << "t " << t;
    ASSERT_EQ(k.perAction.size(), f.perAction.size());
    for (std::size_t i = 0; i < k.perAction.size(); ++i) {
      ASSERT_TRUE(k.perAction[i] == f.perAction[i] ||
                  (std::isnan(k.perAction[i]) && std::isnan(f.perAction[i])));
    }
    ++measured;
  }
  EXPECT_EQ(measured, 12);
}
