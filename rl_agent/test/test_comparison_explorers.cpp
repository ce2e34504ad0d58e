// The paper's comparison explorers (TEXPLORE-VANIR paper §5.1) on hand-made cases: random
// regions, competence progress, prediction error, unknown (R-MAX-style) on the forest model,
// Boltzmann, random and greedy.
#include <gtest/gtest.h>

#include <set>

#include "rl_agent/agent/boltzmann_selector.h"
#include "rl_agent/model/exploration_model.h"
#include "rl_agent/reward/explorer_registry.h"
#include "rl_agent/reward/random_regions.h"
#include "rl_agent/reward/region_error_reward.h"

using namespace rl_agent;
using rl_common::State;

namespace {

FactoredModel::Config forestConfig() {
  FactoredModel::Config c;
  c.numActions = 2;
  c.featMin = {0.0f, 0.0f};
  c.featMax = {10.0f, 10.0f};
  c.episodic = false;
  c.forest.numTrees = 1;
  c.forest.expPct = 1.0;
  c.forest.combination = Combination::Best;
  c.forest.tree.featPct = 0.0;
  return c;
}

std::shared_ptr<const RandomRegions> oneRegion() {
  return std::make_shared<RandomRegions>(std::vector<float>{0, 0}, std::vector<float>{10, 10}, 1,
                                         1);
}

/// Applies `bonus` to an empty prediction for (s, a).
rl_common::StateActionInfo applied(const IntrinsicReward& bonus, const State& s, int a) {
  FactoredModel model(forestConfig(), 1);
  NoveltyIndex visited(2, {0, 0}, {10, 10});
  const auto view = model.factoredView();
  const auto snap = visited.snapshot();
  rl_common::StateActionInfo info;
  bonus.apply(BonusContext{*view, snap, s, a}, &info);
  return info;
}

}  // namespace

TEST(RandomRegions, PartitionsTheBoxDeterministically) {
  const std::vector<float> lo{0, 0, 0}, hi{10, 10, 1};
  RandomRegions a(lo, hi, 8, 7), b(lo, hi, 8, 7), c(lo, hi, 8, 8);
  EXPECT_EQ(a.size(), 8);
  rl_common::Random rng(1);
  std::set<int> seen;
  bool differs = false;
  for (int i = 0; i < 2000; ++i) {
    const State s{float(rng.uniform(0, 10)), float(rng.uniform(0, 10)), float(rng.uniform())};
    const int r = a.regionOf(s);
    ASSERT_GE(r, 0);
    ASSERT_LT(r, 8);
    EXPECT_EQ(r, b.regionOf(s));  // same seed, same regions
    differs |= r != c.regionOf(s);
    seen.insert(r);
  }
  EXPECT_GE(seen.size(), 6u);  // random cuts: most regions get some of the box
  EXPECT_TRUE(differs);
  // One feature, two regions: the two ends of the range fall on different sides of the cut.
  RandomRegions two({0}, {10}, 2, 3);
  EXPECT_NE(two.regionOf({0.0f}), two.regionOf({10.0f}));
  EXPECT_THROW(RandomRegions({}, {}, 2, 1), std::invalid_argument);
}

TEST(RegionErrorReward, PredictionErrorIsOneMinusProbabilityOfWhatHappened) {
  rl_common::StateActionInfo listed;
  listed.transitions = {{{1, 1}, 0.7}, {{2, 1}, 0.3}};
  EXPECT_NEAR(RegionErrorReward::predictionError({{0, 0}, 0, 0, {1, 1}, false}, listed), 0.3,
              1e-12);
  EXPECT_NEAR(RegionErrorReward::predictionError({{0, 0}, 0, 0, {5, 5}, false}, listed), 1.0,
              1e-12);
  rl_common::StateActionInfo factored;
  factored.factored = {{{1.0f, 0.5}, {2.0f, 0.5}}, {{0.0f, 1.0}}};
  EXPECT_NEAR(RegionErrorReward::predictionError({{0, 0}, 0, 0, {1, 0}, false}, factored), 0.5,
              1e-12);
  rl_common::StateActionInfo term;
  term.termProb = 0.25f;
  EXPECT_NEAR(RegionErrorReward::predictionError({{0, 0}, 0, 0, {0, 0}, true}, term), 0.75, 1e-12);
}

TEST(RegionErrorReward, CompetenceIsTheSlopeOfTheErrorCurve) {
  RegionErrorReward::Config c;
  c.kind = RegionErrorReward::Kind::CompetenceProgress;
  c.weight = 2.0;
  c.window = 4;
  RegionErrorReward reward(c, oneRegion());
  EXPECT_DOUBLE_EQ(reward.interest(0), 0.0);  // no curve yet
  rl_common::StateActionInfo wrong, right;
  wrong.transitions = {{{9, 9}, 1.0}};
  right.transitions = {{{1, 1}, 1.0}};
  const rl_common::Experience e{{0, 0}, 0, 0.0f, {1, 1}, false};
  reward.observe(e, wrong);  // errors 1, 1, 0, 0: progress |1 − 0| = 1
  reward.observe(e, wrong);
  reward.observe(e, right);
  reward.observe(e, right);
  EXPECT_DOUBLE_EQ(reward.interest(0), 1.0);
  auto info = applied(*reward.snapshot(), {3, 3}, 1);
  EXPECT_FLOAT_EQ(info.otherReward, 2.0f);
  EXPECT_FLOAT_EQ(info.reward, 2.0f);
  reward.observe(e, right);  // window 1, 0, 0, 0: |0.5 − 0| = 0.5
  EXPECT_DOUBLE_EQ(reward.interest(0), 0.5);
  reward.observe(e, right);  // 0, 0, 0, 0: learned, no progress left
  EXPECT_DOUBLE_EQ(reward.interest(0), 0.0);
}

TEST(RegionErrorReward, PredErrorIsTheMeanRecentError) {
  RegionErrorReward::Config c;
  c.kind = RegionErrorReward::Kind::PredictionError;
  c.weight = 3.0;
  c.window = 4;
  RegionErrorReward reward(c, oneRegion());
  EXPECT_DOUBLE_EQ(reward.interest(0), 1.0);  // nothing predicted yet
  rl_common::StateActionInfo half;
  half.transitions = {{{1, 1}, 0.5}, {{2, 2}, 0.5}};
  reward.observe({{0, 0}, 0, 0.0f, {1, 1}, false}, half);
  reward.observe({{0, 0}, 0, 0.0f, {3, 3}, false}, half);
  EXPECT_DOUBLE_EQ(reward.interest(0), 0.75);  // (0.5 + 1) / 2
  EXPECT_NEAR(applied(*reward.snapshot(), {0, 0}, 0).otherReward, 2.25, 1e-6);
}

TEST(ComparisonExplorers, PredErrorThroughTheForestModel) {
  // The first experience is predicted as a self-transition, so its error is 1: with one
  // region, the bonus everywhere is the weight. A repeated experience the tree has learned
  // lowers the mean error.
  ExplorerSettings s;
  s.v = 1.5f;
  s.featMin = {0, 0};
  s.featMax = {10, 10};
  s.regions = 1;
  const auto explorer = explorerRegistry().create("prederror", s);
  ASSERT_EQ(explorer->learners.size(), 1u);
  ExplorationModel model(forestConfig(), 1, explorer->rewards, explorer->learners);
  EXPECT_NEAR(model.explorationView()->query({5, 5}, 0).otherReward, 1.5, 1e-6);
  const rl_common::Experience e{{1, 1}, 0, 0.0f, {2, 1}, false};
  model.update({e});
  EXPECT_NEAR(model.explorationView()->query({5, 5}, 1).otherReward, 1.5, 1e-6);
  model.update({e});  // now predicted: error 0, mean 0.5
  EXPECT_NEAR(model.explorationView()->query({5, 5}, 1).otherReward, 0.75, 1e-6);
  model.setIntrinsicEnabled(false);
  EXPECT_FLOAT_EQ(model.explorationView()->query({5, 5}, 1).otherReward, 0.0f);
}

TEST(ComparisonExplorers, UnknownOnTheForestModelIsRmaxStyle) {
  ExplorerSettings s;
  s.m = 2;
  s.rmax = 100.0f;
  const auto explorer = explorerRegistry().create("unknown", s);
  ExplorationModel model(forestConfig(), 1, explorer->rewards);
  const rl_common::Experience e{{1, 1}, 0, 1.0f, {1, 2}, false};
  model.update({e});
  auto info = model.explorationView()->query({1, 1}, 0);
  EXPECT_FLOAT_EQ(info.reward, 100.0f);  // visited once < m: terminal reward Rmax
  EXPECT_FLOAT_EQ(info.termProb, 1.0f);
  model.update({e});
  info = model.explorationView()->query({1, 1}, 0);
  EXPECT_NEAR(info.reward, 1.0f, 1e-5);  // known: the forest's prediction
  EXPECT_FLOAT_EQ(info.termProb, 0.0f);
}

TEST(ComparisonExplorers, SelectionExplorersAddNoBonus) {
  ExplorerSettings s;
  s.tau = 0.5f;
  const auto random = explorerRegistry().create("random", s);
  EXPECT_TRUE(random->randomActions);
  EXPECT_TRUE(random->rewards.empty() && random->learners.empty());
  const auto boltzmann = explorerRegistry().create("boltzmann", s);
  EXPECT_TRUE(boltzmann->boltzmann);
  EXPECT_FLOAT_EQ(boltzmann->tau, 0.5f);
  const auto greedy = explorerRegistry().create("greedy", s);
  EXPECT_FALSE(greedy->randomActions || greedy->boltzmann || greedy->epsilonGreedy);
  EXPECT_TRUE(greedy->rewards.empty() && greedy->learners.empty());
  s.tau = 0.0f;
  EXPECT_THROW(explorerRegistry().create("boltzmann", s), std::invalid_argument);
  EXPECT_THROW(explorerRegistry().create("competence", ExplorerSettings{}),
               std::invalid_argument);  // needs feature ranges
}

TEST(BoltzmannSelector, SoftmaxProbabilitiesAndSampling) {
  const auto p = BoltzmannSelector::probabilities({0.0, 0.2}, 0.2);
  EXPECT_NEAR(p[1], std::exp(1.0) / (1.0 + std::exp(1.0)), 1e-12);
  EXPECT_NEAR(p[0] + p[1], 1.0, 1e-12);
  // Large values do not overflow.
  const auto big = BoltzmannSelector::probabilities({1000.0, 1000.0, 0.0}, 0.2);
  EXPECT_NEAR(big[0], 0.5, 1e-12);
  rl_common::Random rng(9);
  int ones = 0;
  for (int i = 0; i < 20000; ++i) ones += BoltzmannSelector::sample({0.0, 0.2}, 0.2, rng);
  EXPECT_NEAR(ones / 20000.0, p[1], 0.015);
  EXPECT_THROW(BoltzmannSelector::probabilities({1.0}, 0.0), std::invalid_argument);
}
