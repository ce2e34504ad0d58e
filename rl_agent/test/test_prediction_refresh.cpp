// ModelView::refresh(): a prediction kept across model versions and brought up to date must be
// bit for bit what a new query returns, whatever changed in between (FactoredModel,
// ExplorationModel with each kind of bonus, DeferringView), and it must actually reuse what did
// not change.
#include <gtest/gtest.h>

#include <memory>
#include <vector>

#include "rl_agent/agent/irreversible_step.h"
#include "rl_agent/model/exploration_model.h"
#include "rl_agent/model/factored_model.h"
#include "rl_agent/reward/novelty_reward.h"
#include "rl_agent/reward/unknown_reward.h"
#include "rl_agent/reward/unvisited_action_reward.h"
#include "rl_agent/reward/variance_reward.h"
#include "rl_common/random.h"

using rl_agent::ExplorationModel;
using rl_agent::FactoredModel;
using rl_common::Experience;
using rl_common::PredictionStamp;
using rl_common::State;
using rl_common::StateActionInfo;

namespace {

constexpr int kActions = 4;

// A 3-feature grid (x, y in 0..4, a lamp 0/1) with noisy moves: 0 left, 1 right, 2 up, 3
// toggles the lamp; a move fails with probability 0.2. Reward 1 for lighting the lamp at (4, 4),
// which ends the episode.
Experience step(const State& s, int a, rl_common::Random& rng) {
  State next = s;
  const bool fails = rng.uniform() < 0.2;
  if (!fails) {
    if (a == 0) next[0] = std::max(0.0f, s[0] - 1);
    if (a == 1) next[0] = std::min(4.0f, s[0] + 1);
    if (a == 2) next[1] = s[1] == 4.0f ? 0.0f : s[1] + 1;
    if (a == 3) next[2] = 1.0f - s[2];
  }
  const bool goal = next[2] == 1.0f && s[2] == 0.0f && s[0] == 4.0f && s[1] == 4.0f;
  return {s, a, goal ? 1.0f : 0.0f, next, goal};
}

FactoredModel::Config gridConfig(rl_agent::Combination combination, bool episodic) {
  FactoredModel::Config c;
  c.numActions = kActions;
  c.featMin = {0.0f, 0.0f, 0.0f};
  c.featMax = {4.0f, 4.0f, 1.0f};
  c.episodic = episodic;
  c.forest.numTrees = 5;
  c.forest.combination = combination;
  return c;
}

std::vector<State> allStates() {
  std::vector<State> out;
  for (int x = 0; x <= 4; ++x) {
    for (int y = 0; y <= 4; ++y) {
      for (int l = 0; l <= 1; ++l) out.push_back({float(x), float(y), float(l)});
    }
  }
  return out;
}

void expectSame(const StateActionInfo& kept, const StateActionInfo& fresh, const char* what) {
  ASSERT_EQ(kept.factored, fresh.factored) << what;
  ASSERT_EQ(kept.transitions, fresh.transitions) << what;
  ASSERT_EQ(kept.reward, fresh.reward) << what;
  ASSERT_EQ(kept.termProb, fresh.termProb) << what;
  ASSERT_EQ(kept.known, fresh.known) << what;
  ASSERT_EQ(kept.externalReward, fresh.externalReward) << what;
  ASSERT_EQ(kept.varianceReward, fresh.varianceReward) << what;
  ASSERT_EQ(kept.noveltyReward, fresh.noveltyReward) << what;
  ASSERT_EQ(kept.otherReward, fresh.otherReward) << what;
}

/// Feeds a random walk one experience at a time to `model` and, after each, refreshes a kept
/// prediction of every state-action (every other one skips a version, so stamps also come
/// from two or more versions back) and compares it with a new query. Returns how many
/// refreshes reused the kept feature distributions of at least one feature.
template <typename Model, typename Query>
long walkAndCompare(Model& model, Query viewOf, std::uint64_t seed, int steps) {
  rl_common::Random rng(seed);
  const std::vector<State> states = allStates();
  std::vector<StateActionInfo> kept(states.size() * kActions);
  std::vector<PredictionStamp> stamps(kept.size());
  long reused = 0;
  State s = {0.0f, 0.0f, 0.0f};
  for (int t = 0; t < steps; ++t) {
    const Experience e = step(s, rng.uniformInt(0, kActions - 1), rng);
    model.update({e});
    s = e.terminal ? State{0.0f, 0.0f, 0.0f} : e.next;
    const auto view = viewOf(model);
    for (std::size_t i = 0; i < kept.size(); ++i) {
      if ((i + static_cast<std::size_t>(t)) % 2 == 1) continue;  // skip this version
      const State& q = states[i / kActions];
      const int a = static_cast<int>(i % kActions);
      std::vector<const void*> before;
      for (const auto& f : kept[i].factored) before.push_back(f.data());
      view->refresh(q, a, kept[i], stamps[i]);
      for (std::size_t j = 0; j < before.size() && j < kept[i].factored.size(); ++j) {
        if (before[j] == kept[i].factored[j].data()) {
          ++reused;
          break;
        }
      }
      expectSame(kept[i], view->query(q, a), "refresh against query");
      if (::testing::Test::HasFatalFailure()) return reused;
    }
  }
  return reused;
}

}  // namespace

TEST(PredictionRefresh, AFactoredModelsKeptPredictionsEqualNewQueries) {
  using rl_agent::Combination;
  for (Combination c : {Combination::Average, Combination::WeightedAverage, Combination::Best,
                        Combination::Separate}) {
    for (bool episodic : {true, false}) {
      FactoredModel model(gridConfig(c, episodic), 3);
      const long reused = walkAndCompare(
          model, [](const FactoredModel& m) { return m.factoredView(); }, 11, 150);
      ASSERT_FALSE(::testing::Test::HasFatalFailure())
          << "combination " << int(c) << " episodic " << episodic;
      // The trees rebuild on a minority of the instances: most refreshes re-read few forests.
      if (c == Combination::Average) {
        EXPECT_GT(reused, 1000) << "episodic " << episodic;
      }
    }
  }
}

TEST(PredictionRefresh, TheVarianceOfARefreshEqualsTheFusedQuerys) {
  FactoredModel model(gridConfig(rl_agent::Combination::Average, true), 5);
  rl_common::Random rng(2);
  const std::vector<State> states = allStates();
  std::vector<StateActionInfo> kept(states.size() * kActions);
  std::vector<PredictionStamp> stamps(kept.size());
  State s = {0.0f, 0.0f, 0.0f};
  for (int t = 0; t < 80; ++t) {
    const Experience e = step(s, rng.uniformInt(0, kActions - 1), rng);
    model.update({e});
    s = e.terminal ? State{0.0f, 0.0f, 0.0f} : e.next;
    const auto view = model.factoredView();
    for (std::size_t i = 0; i < kept.size(); ++i) {
      const State& q = states[i / kActions];
      const int a = static_cast<int>(i % kActions);
      double kv = -1.0, fv = -2.0;
      // Every third refresh asks for no variance: the stamp must still serve one later.
      view->refresh(q, a, kept[i], &stamps[i], (t + int(i)) % 3 == 0 ? nullptr : &kv);
      const StateActionInfo fresh = view->query(q, a, &fv);
      expectSame(kept[i], fresh, "refresh with variance");
      if ((t + int(i)) % 3 != 0) {
        ASSERT_EQ(kv, fv) << "t " << t << " i " << i;
      }
    }
  }
}

TEST(PredictionRefresh, ExplorationBonusesAreAppliedAfreshOnAKeptPrediction) {
  // Novelty changes with every experience, the unvisited-action bonus with every visit, and
  // the R-MAX-style bonus overwrites termProb: none of it may leak from a kept prediction.
  for (int kind = 0; kind < 3; ++kind) {
    ExplorationModel::Rewards rewards;
    if (kind == 0) {
      rewards = {std::make_shared<rl_agent::VarianceReward>(1.0),
                 std::make_shared<rl_agent::NoveltyReward>(3.0)};
    } else if (kind == 1) {
      rewards = {std::make_shared<rl_agent::UnvisitedActionReward>(0.5f)};
    } else {
      rewards = {std::make_shared<rl_agent::UnknownReward>(2, 50.0f)};
    }
    ExplorationModel model(gridConfig(rl_agent::Combination::Average, true), 7, rewards);
    walkAndCompare(
        model, [](const ExplorationModel& m) { return m.explorationView(); }, 13, 120);
    ASSERT_FALSE(::testing::Test::HasFatalFailure()) << "bonus kind " << kind;
    // Intrinsic rewards switched off (the task phase): the kept predictions lose the bonuses.
    model.setIntrinsicEnabled(false);
    walkAndCompare(
        model, [](const ExplorationModel& m) { return m.explorationView(); }, 17, 20);
    ASSERT_FALSE(::testing::Test::HasFatalFailure()) << "bonus kind " << kind << " off";
  }
}

TEST(PredictionRefresh, ADeferredStepIsNotReusedOnceItIsNoLongerDeferred) {
  ExplorationModel model(gridConfig(rl_agent::Combination::Average, true), 7,
                         {std::make_shared<rl_agent::NoveltyReward>(3.0)});
  rl_common::Random rng(4);
  State s = {0.0f, 0.0f, 0.0f};
  for (int t = 0; t < 60; ++t) {
    const Experience e = step(s, rng.uniformInt(0, kActions - 1), rng);
    model.update({e});
    s = e.terminal ? State{0.0f, 0.0f, 0.0f} : e.next;
  }
  rl_agent::OneWaySignature toggle;  // toggling the lamp where it is off
  toggle.action = 3;
  toggle.changes = {{2, 0.0f, 1.0f}};
  const auto deferring = std::make_shared<rl_agent::DeferringView>(
      model.view(), std::make_shared<const std::vector<rl_agent::OneWaySignature>>(
                        std::vector<rl_agent::OneWaySignature>{toggle}));
  const State dark = {2.0f, 2.0f, 0.0f};
  StateActionInfo kept;
  PredictionStamp stamp;
  deferring->refresh(dark, 3, kept, stamp);
  EXPECT_EQ(kept.termProb, 1.0f);
  EXPECT_EQ(kept.reward, 0.0f);
  expectSame(kept, deferring->query(dark, 3), "deferred");
  // The same model without the deferral, and the next version of it: the base's own values.
  model.view()->refresh(dark, 3, kept, stamp);
  expectSame(kept, model.view()->query(dark, 3), "after the deferral");
  EXPECT_GT(kept.noveltyReward + kept.otherReward + kept.externalReward, -1.0f);
  model.update({step(dark, 3, rng)});
  model.view()->refresh(dark, 3, kept, stamp);
  expectSame(kept, model.view()->query(dark, 3), "next version");
  // A state no signature applies to goes through the base's refresh.
  const State lit = {2.0f, 2.0f, 1.0f};
  StateActionInfo litKept;
  PredictionStamp litStamp;
  model.view()->refresh(lit, 3, litKept, litStamp);
  model.update({step(lit, 0, rng)});
  deferring->refresh(lit, 3, litKept, litStamp);  // the deferring view's base is a version back
  expectSame(litKept, deferring->query(lit, 3), "not deferred");
}

TEST(PredictionRefresh, StampsOfAnotherModelAreNotTrusted) {
  // Two models with the same seed and configuration learn different data: the second one's
  // view must recompute a prediction stamped by the first.
  FactoredModel first(gridConfig(rl_agent::Combination::Average, true), 3);
  FactoredModel second(gridConfig(rl_agent::Combination::Average, true), 3);
  rl_common::Random rng(9);
  const State s0 = {0.0f, 0.0f, 0.0f};
  for (int t = 0; t < 40; ++t) first.update({step(s0, 1, rng)});
  for (int t = 0; t < 40; ++t) second.update({step(s0, 0, rng)});
  StateActionInfo kept;
  PredictionStamp stamp;
  first.factoredView()->refresh(s0, 1, kept, stamp);
  second.factoredView()->refresh(s0, 1, kept, stamp);
  expectSame(kept, second.factoredView()->query(s0, 1), "second model");
}
