#include "rl_agent/model/factored_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "rl_agent/model/exploration_model.h"
#include "rl_agent/reward/novelty_reward.h"
#include "rl_agent/reward/unknown_reward.h"
#include "rl_agent/reward/variance_reward.h"

using rl_agent::ExplorationModel;
using rl_agent::FactoredModel;
using rl_common::Experience;
using rl_common::State;

namespace {

// A deterministic 1-D corridor of 6 cells: action 0 left, 1 right, 2 stays;
// walls at both ends; reward 1 for stepping onto cell 5, which ends the
// episode.
Experience corridor(int x, int a) {
  int next = x + (a == 0 ? -1 : a == 1 ? 1 : 0);
  next = std::max(0, std::min(5, next));
  return {{float(x)}, a, next == 5 && x != 5 ? 1.0f : 0.0f, {float(next)}, next == 5 && x != 5};
}

FactoredModel::Config corridorConfig(int trees) {
  FactoredModel::Config c;
  c.numActions = 3;
  c.featMin = {0.0f};
  c.featMax = {5.0f};
  c.episodic = true;
  c.forest.numTrees = trees;
  return c;
}

std::vector<Experience> allCorridorExperiences() {
  std::vector<Experience> all;
  for (int rep = 0; rep < 3; ++rep) {
    for (int x = 0; x < 5; ++x) {
      for (int a = 0; a < 3; ++a) all.push_back(corridor(x, a));
    }
  }
  return all;
}

}  // namespace

TEST(FactoredModel, UnknownBeforeAnyData) {
  FactoredModel model(corridorConfig(5), 1);
  const auto info = model.view()->query({2.0f}, 1);
  EXPECT_FALSE(info.known);
  ASSERT_EQ(info.transitions.size(), 1u);
  EXPECT_EQ(info.transitions[0].first, State{2.0f});
  EXPECT_FLOAT_EQ(info.reward, -0.001f);
}

TEST(FactoredModel, PredictsADeterministicDomainExactly) {
  // One tree without randomisation gives exact predictions once every
  // transition was seen.
  auto config = corridorConfig(1);
  config.forest.tree.featPct = 0.0;
  config.forest.combination = rl_agent::Combination::Best;
  FactoredModel model(config, 2);
  model.update(allCorridorExperiences());
  const auto view = model.factoredView();
  for (int x = 0; x < 5; ++x) {
    for (int a = 0; a < 3; ++a) {
      const Experience truth = corridor(x, a);
      const auto info = view->query({float(x)}, a);
      ASSERT_TRUE(info.known);
      const auto next = rl_common::expandTransitions(info);
      ASSERT_EQ(next.size(), 1u) << "x=" << x << " a=" << a;
      if (!truth.terminal) {
        EXPECT_EQ(next[0].first, truth.next);
      }
      EXPECT_NEAR(next[0].second, 1.0, 1e-9);
      EXPECT_NEAR(info.reward, truth.reward, 1e-6) << "x=" << x << " a=" << a;
      EXPECT_NEAR(info.termProb, truth.terminal ? 1.0 : 0.0, 1e-6);
      EXPECT_NEAR(view->variance({float(x)}, a), 0.0, 1e-12);
    }
  }
}

TEST(FactoredModel, RelativeTransitionsGeneraliseAcrossStates) {
  // Trained on cells 0..2 only, "move right" is +1 everywhere, so cell 3 is
  // predicted too.
  auto config = corridorConfig(1);
  config.forest.tree.featPct = 0.0;
  config.forest.combination = rl_agent::Combination::Best;
  FactoredModel model(config, 3);
  std::vector<Experience> some;
  for (int rep = 0; rep < 3; ++rep) {
    for (int x = 1; x < 3; ++x) some.push_back(corridor(x, 1));
  }
  model.update(some);
  const auto next = rl_common::expandTransitions(model.view()->query({3.0f}, 1));
  ASSERT_EQ(next.size(), 1u);
  EXPECT_EQ(next[0].first, State{4.0f});
}

TEST(FactoredModel, IndependentProductOverFeatures) {
  // Two features, each flipping independently: 4 outcomes with probability 1/4.
  FactoredModel::Config c;
  c.numActions = 1;
  c.featMin = {0.0f, 0.0f};
  c.featMax = {1.0f, 1.0f};
  c.episodic = false;
  c.forest.numTrees = 1;
  c.forest.tree.featPct = 0.0;
  c.forest.combination = rl_agent::Combination::Best;
  FactoredModel model(c, 4);
  std::vector<Experience> data;
  for (int i = 0; i < 4; ++i) {
    data.push_back({{0.0f, 0.0f}, 0, 0.0f, {float(i & 1), float((i >> 1) & 1)}, false});
  }
  model.update(data);
  const auto info = model.view()->query({0.0f, 0.0f}, 0);
  ASSERT_EQ(info.factored.size(), 2u);  // one distribution per feature
  EXPECT_TRUE(info.transitions.empty());
  const auto next = rl_common::expandTransitions(info);
  ASSERT_EQ(next.size(), 4u);
  double total = 0;
  for (const auto& [s, p] : next) {
    EXPECT_NEAR(p, 0.25, 1e-9);
    EXPECT_NEAR(rl_common::transitionProbability(info, s), 0.25, 1e-9);
    total += p;
  }
  EXPECT_NEAR(total, 1.0, 1e-12);
  EXPECT_DOUBLE_EQ(rl_common::transitionProbability(info, {0.5f, 0.0f}), 0.0);
  EXPECT_FLOAT_EQ(info.termProb, 0.0f);  // non-episodic
}

TEST(FactoredModel, OneQueryWithVarianceEqualsTheTwoCalls) {
  // The planner's fused query descends each tree once for the prediction and D(s, a); the
  // values must be exactly those of query() and variance(), for every combination.
  for (const char* combo : {"average", "weighted", "best", "separate"}) {
    for (bool episodic : {true, false}) {
      auto config = corridorConfig(5);
      config.episodic = episodic;
      config.forest.combination = rl_agent::combinationFromName(combo);
      FactoredModel model(config, 9);
      const auto empty = model.factoredView();
      double v = -1.0;
      empty->query({2.0f}, 1, &v);
      EXPECT_EQ(v, empty->variance({2.0f}, 1));
      // Noisy data, so the trees disagree somewhere.
      std::vector<Experience> data = allCorridorExperiences();
      for (int x = 0; x < 5; ++x) data.push_back({{float(x)}, 2, 0.5f, {float(x + 1)}, false});
      model.update(data);
      const auto view = model.factoredView();
      double disagreeing = 0.0;
      for (int x = 0; x <= 5; ++x) {
        for (int a = 0; a < 3; ++a) {
          double d = -1.0;
          const auto fused = view->query({float(x)}, a, &d);
          const auto plain = view->query({float(x)}, a);
          ASSERT_EQ(d, view->variance({float(x)}, a)) << combo << " x=" << x << " a=" << a;
          ASSERT_EQ(fused.factored, plain.factored);
          ASSERT_EQ(fused.reward, plain.reward);
          ASSERT_EQ(fused.termProb, plain.termProb);
          disagreeing += d;
        }
      }
      EXPECT_GT(disagreeing, 0.0) << combo;
    }
  }
}

TEST(FactoredModel, RecombinedViewPlansOnTheWholeForest) {
  // --combo separate predicts with tree 0; the view recombined as average (--taskcombo) mixes
  // the same trees, and recombined as separate again predicts as the original view.
  auto config = corridorConfig(5);
  config.forest.combination = rl_agent::Combination::Separate;
  FactoredModel model(config, 9);
  std::vector<Experience> data = allCorridorExperiences();
  for (int x = 0; x < 5; ++x) data.push_back({{float(x)}, 2, 0.5f, {float(x + 1)}, false});
  model.update(data);
  const auto view = model.factoredView();
  const auto average = view->recombined(rl_agent::Combination::Average);
  const auto same = average->recombined(rl_agent::Combination::Separate);
  int differing = 0;
  for (int x = 0; x <= 5; ++x) {
    for (int a = 0; a < 3; ++a) {
      const State s{float(x)};
      EXPECT_EQ(same->featureDistribution(s, a, 0), view->featureDistribution(s, a, 0));
      EXPECT_EQ(same->query(s, a).reward, view->query(s, a).reward);
      EXPECT_EQ(average->variance(s, a), view->variance(s, a));  // the same trees
      differing += average->featureDistribution(s, a, 0) != view->featureDistribution(s, a, 0);
    }
  }
  EXPECT_GT(differing, 0) << "the trees disagree somewhere, so the average is not tree 0";
}

TEST(FactoredModel, RejectsMalformedExperiences) {
  FactoredModel model(corridorConfig(2), 1);
  EXPECT_THROW(model.update({{{1.0f, 2.0f}, 0, 0.0f, {1.0f}, false}}), std::invalid_argument);
  EXPECT_THROW(model.update({{{1.0f}, 3, 0.0f, {1.0f}, false}}), std::invalid_argument);
  EXPECT_THROW(model.view()->query({1.0f}, -1), std::invalid_argument);
  FactoredModel::Config bad = corridorConfig(2);
  bad.featMax = {};
  EXPECT_THROW(FactoredModel(bad, 1), std::invalid_argument);
}

TEST(ExplorationModel, BonusesAreAddedAndBrokenDown) {
  ExplorationModel::Rewards rewards{std::make_shared<rl_agent::VarianceReward>(1.0),
                                    std::make_shared<rl_agent::NoveltyReward>(3.0)};
  ExplorationModel model(corridorConfig(5), 5, rewards);
  model.update({corridor(1, 1), corridor(1, 1)});
  const auto view = model.explorationView();
  // (1, right) was visited: no novelty; (3, right) is 2/5 away, d = 1: novelty
  // 3 * 0.4.
  const auto seen = view->query({1.0f}, 1);
  EXPECT_FLOAT_EQ(seen.noveltyReward, 0.0f);
  const auto far = view->query({3.0f}, 1);
  EXPECT_NEAR(far.noveltyReward, 1.2f, 1e-6);
  const auto never = view->query({3.0f}, 0);  // action 0 never taken: delta = 1
  EXPECT_NEAR(never.noveltyReward, 3.0f, 1e-6);
  for (const auto& info : {seen, far, never}) {
    EXPECT_NEAR(info.reward,
                info.externalReward + info.varianceReward + info.noveltyReward + info.otherReward,
                1e-5);
    EXPECT_GE(info.varianceReward, 0.0f);
  }
  // The variance part equals v * D(s, a).
  EXPECT_NEAR(never.varianceReward, view->model().variance({3.0f}, 0), 1e-6);
}

TEST(ExplorationModel, IntrinsicRewardsCanBeSwitchedOff) {
  ExplorationModel model(corridorConfig(3), 6, {std::make_shared<rl_agent::NoveltyReward>(3.0)});
  model.update({corridor(1, 1)});
  EXPECT_GT(model.view()->query({4.0f}, 2).reward, 1.0f);
  model.setIntrinsicEnabled(false);
  const auto info = model.view()->query({4.0f}, 2);
  EXPECT_FLOAT_EQ(info.noveltyReward, 0.0f);
  EXPECT_FLOAT_EQ(info.reward, info.externalReward);
}

TEST(ExplorationModel, UnknownRewardIsOptimisticUntilMVisits) {
  ExplorationModel model(corridorConfig(2), 7,
                         {std::make_shared<rl_agent::UnknownReward>(2, 50.0f)});
  model.update({corridor(1, 1)});
  auto info = model.view()->query({1.0f}, 1);
  EXPECT_FLOAT_EQ(info.reward, 50.0f);
  EXPECT_FLOAT_EQ(info.termProb, 1.0f);
  model.update({corridor(1, 1)});
  info = model.view()->query({1.0f}, 1);
  EXPECT_LT(info.reward, 1.0f);
  EXPECT_FLOAT_EQ(info.otherReward, 0.0f);
}

TEST(ExplorationModel, StateNoveltyIgnoresWhichActionWasTaken) {
  // Action 1 was taken at 1. Per state-action (the original), action 2 was never taken, so its
  // novelty is 1 everywhere (bonus 3); per state, state 1 is known (0) and state 3 is
  // |3 − 1| / 5 away (bonus 3 · 0.4).
  for (bool perState : {false, true}) {
    ExplorationModel model(corridorConfig(3), 6,
                           {std::make_shared<rl_agent::NoveltyReward>(3.0, perState)});
    model.update({corridor(1, 1)});
    const auto view = model.view();
    EXPECT_NEAR(view->query({1.0f}, 2).noveltyReward, perState ? 0.0 : 3.0, 1e-5) << perState;
    EXPECT_NEAR(view->query({3.0f}, 2).noveltyReward, perState ? 1.2 : 3.0, 1e-5) << perState;
    EXPECT_NEAR(view->query({3.0f}, 1).noveltyReward, 1.2, 1e-5) << perState;
  }
}
