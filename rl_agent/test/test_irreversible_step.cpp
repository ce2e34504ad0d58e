// One-way steps learned from the agent's own steps, and the explorer that defers them
// (StepDeferral, DeferringView).
#include <gtest/gtest.h>

#include <stdexcept>

#include "rl_agent/agent/irreversible_step.h"

namespace rl_agent {
namespace {

using rl_common::State;

/// A corridor x in 0..4 with a key at x == 2: actions east (0), west (1), pickup (2: sets
/// have_key and darkens the key's two lights), wait (3). Nothing gives the key back.
/// State = {x, have_key, light_a, light_b}: the lights are 5 on the key, 0 elsewhere or once
/// the key is held.
constexpr int kEast = 0, kWest = 1, kPickup = 2, kWait = 3;

class KeyCorridor : public rl_common::ModelView {
 public:
  rl_common::StateActionInfo query(const State& s, int a) const override {
    State next = s;
    if (a == kEast) next[0] = std::min(4.0f, s[0] + 1.0f);
    if (a == kWest) next[0] = std::max(0.0f, s[0] - 1.0f);
    if (a == kPickup && s[0] == 2.0f) next[1] = 1.0f;
    next[2] = next[3] = (next[1] == 0.0f && next[0] == 2.0f) ? 5.0f : 0.0f;
    rl_common::StateActionInfo info;
    info.known = true;
    info.reward = 1.0f;
    info.noveltyReward = 1.0f;
    for (float v : next) info.factored.push_back({{v, 1.0}});
    return info;
  }
};

/// The same corridor where the model is unsure a step west comes back: the old position keeps
/// only `p` of the probability (a forest's averaged prediction).
class UnsureCorridor : public rl_common::ModelView {
 public:
  explicit UnsureCorridor(double p) : p_(p) {}
  rl_common::StateActionInfo query(const State& s, int a) const override {
    rl_common::StateActionInfo info = KeyCorridor().query(s, a);
    if (a == kWest && s[0] > 0.0f) info.factored[0] = {{s[0] - 1.0f, p_}, {s[0], 1.0 - p_}};
    return info;
  }

 private:
  double p_;
};

const State kOnKey{2, 0, 5, 5};
const State kHeld{2, 1, 0, 0};
const std::vector<std::size_t> kNone;

/// Waits `n` steps where it stands (a reversible step: nothing changes).
void wait(StepDeferral& d, const rl_common::ModelView& m, const State& s, int n) {
  for (int i = 0; i < n; ++i) d.observe(m, s, kWait, s, 4);
}

/// Teaches `d` that the pickup is one-way: the pickup, then the confirmation window.
void learnThePickup(StepDeferral& d, const rl_common::ModelView& m) {
  d.observe(m, {}, -1, kOnKey, 4);
  d.observe(m, kOnKey, kPickup, kHeld, 4);
  wait(d, m, kHeld, 100);
}

TEST(IrreversibleStep, AMoveCanBeUndoneAndPickingTheKeyUpCannot) {
  const KeyCorridor m;
  EXPECT_EQ(unrestorableFeatures(m, {1, 0, 0, 0}, kOnKey, 4), kNone);
  EXPECT_EQ(unrestorableFeatures(m, kOnKey, kOnKey, 4), kNone);  // nothing changed
  EXPECT_EQ(unrestorableFeatures(m, kOnKey, kHeld, 4), (std::vector<std::size_t>{1, 2, 3}));
  EXPECT_EQ(unrestorableFeatures(m, kOnKey, {2, 1}, 4), kNone);  // lengths differ
}

TEST(IrreversibleStep, AnUnsureWayBackStillCountsAsAWayBack) {
  EXPECT_EQ(unrestorableFeatures(UnsureCorridor(0.3), {1, 0, 0, 0}, kOnKey, 4), kNone);
  EXPECT_EQ(unrestorableFeatures(UnsureCorridor(0.0), {1, 0, 0, 0}, kOnKey, 4),
            (std::vector<std::size_t>{0}));
}

TEST(IrreversibleStep, AModelWithNoDataOnSomeActionMarksNothing) {
  class Unknown : public rl_common::ModelView {
   public:
    rl_common::StateActionInfo query(const State&, int) const override { return {}; }
  } m;
  EXPECT_EQ(unrestorableFeatures(m, kOnKey, kHeld, 4), kNone);
}

TEST(IrreversibleStep, ASignatureAppliesToItsActionWhereMostOldValuesHold) {
  OneWaySignature sig;
  sig.action = kPickup;
  sig.changes = {{1, 0.0f, 1.0f}, {2, 5.0f, 0.0f}, {3, 5.0f, 0.0f}};
  EXPECT_TRUE(sig.appliesTo({3, 0, 5, 5}, kPickup)) << "another place, the same key lights";
  EXPECT_TRUE(sig.appliesTo({2, 0, 5, 4}, kPickup));   // two of three old values
  EXPECT_FALSE(sig.appliesTo({2, 0, 4, 4}, kPickup));  // one of three
  EXPECT_FALSE(sig.appliesTo(kOnKey, kEast));
}

TEST(StepDeferral, ConfirmsAOneWayStepAfterItsWindowAndPutsTheNextOneOff) {
  const KeyCorridor m;
  rl_common::Random rng(1);
  StepDeferral d(300);
  const std::vector<double> q = {0.1, 0.5, 0.9, 0.2};  // pickup valued highest
  d.observe(m, {}, -1, kOnKey, 4);
  d.observe(m, kOnKey, kPickup, kHeld, 4);
  wait(d, m, kHeld, 99);
  EXPECT_TRUE(d.signatures().empty()) << "confirmed before its window";
  EXPECT_FALSE(d.active());
  EXPECT_EQ(d.choose(kOnKey, kPickup, q, rng), kPickup);
  wait(d, m, kHeld, 1);
  ASSERT_EQ(d.signatures().size(), 1u);
  EXPECT_EQ(d.signatures()[0].action, kPickup);
  EXPECT_EQ(d.signatures()[0].changes.size(), 3u);
  EXPECT_EQ(d.stepsInRegion(), 100) << "the region began at the pickup";
  EXPECT_TRUE(d.active());
  // A new episode, the key on the floor again: the pickup is put off.
  d.observe(m, {}, -1, kOnKey, 4);
  EXPECT_TRUE(d.oneWay(kOnKey, kPickup));
  EXPECT_FALSE(d.oneWay(kOnKey, kEast));
  EXPECT_FALSE(d.oneWay({1, 0, 0, 0}, kPickup)) << "pickup away from the key is harmless";
  EXPECT_EQ(d.choose(kOnKey, kPickup, q, rng), kWest);  // the best other action
  EXPECT_EQ(d.choose(kOnKey, kWait, q, rng), kWait);    // a reversible choice stands
  EXPECT_EQ(d.deferred(), 1);
  wait(d, m, kOnKey, 300);
  EXPECT_FALSE(d.active()) << "the region's steps are used";
  EXPECT_EQ(d.choose(kOnKey, kPickup, q, rng), kPickup);
  d.observe(m, kOnKey, kPickup, kHeld, 4);  // a known one-way step starts a new region
  EXPECT_EQ(d.stepsInRegion(), 0);
  wait(d, m, kHeld, 100);
  EXPECT_EQ(d.signatures().size(), 1u) << "the same signature is recorded once";
}

TEST(StepDeferral, DefersOnlyInTheFirstRegionsWhenLimited) {
  const KeyCorridor m;
  rl_common::Random rng(1);
  const std::vector<double> q = {0.1, 0.5, 0.9, 0.2};  // pickup valued highest
  StepDeferral limited(300, 1), unlimited(300);
  for (StepDeferral* d : {&limited, &unlimited}) {
    learnThePickup(*d, m);  // the confirmation begins region 1 at the pickup
    EXPECT_EQ(d->regions(), 1);
    EXPECT_TRUE(d->active());
    d->observe(m, {}, -1, kOnKey, 4);  // a new episode: no new region counted
    EXPECT_EQ(d->regions(), 1);
    EXPECT_EQ(d->choose(kOnKey, kPickup, q, rng), kWest);
    d->observe(m, kOnKey, kPickup, kHeld, 4);  // a known one-way step: region 2
    EXPECT_EQ(d->regions(), 2);
    EXPECT_EQ(d->stepsInRegion(), 0);
  }
  EXPECT_FALSE(limited.active()) << "past its one region";
  EXPECT_EQ(limited.planningKey(), nullptr);
  EXPECT_EQ(limited.choose(kOnKey, kPickup, q, rng), kPickup);
  EXPECT_TRUE(unlimited.active());
  EXPECT_EQ(unlimited.choose(kOnKey, kPickup, q, rng), kWest);
  EXPECT_THROW(StepDeferral(300, -1), std::invalid_argument);
}

TEST(StepDeferral, ThePlannersModelEndsAOneWayStepWithNoReward) {
  auto m = std::make_shared<const KeyCorridor>();
  StepDeferral d(300);
  EXPECT_EQ(d.planningView(m), m) << "nothing to defer yet: the model itself";
  learnThePickup(d, *m);
  const auto view = d.planningView(m);
  ASSERT_NE(view, m);
  const auto pickup = view->query(kOnKey, kPickup);
  EXPECT_EQ(pickup.termProb, 1.0f);
  EXPECT_EQ(pickup.reward, 0.0f);
  EXPECT_EQ(pickup.noveltyReward, 0.0f);
  const auto east = view->query(kOnKey, kEast);
  EXPECT_EQ(east.termProb, 0.0f);
  EXPECT_EQ(east.reward, 1.0f);
}

TEST(StepDeferral, ForgetsACandidateThatARealStepUndoes) {
  // A model that knows nothing about going back yet: every action keeps the state.
  class Stuck : public rl_common::ModelView {
   public:
    rl_common::StateActionInfo query(const State& s, int) const override {
      rl_common::StateActionInfo info;
      info.known = true;
      for (float v : s) info.factored.push_back({{v, 1.0}});
      return info;
    }
  } m;
  StepDeferral d(300);
  const State a{1, 0, 0, 0}, b{2, 0, 5, 5};  // a move that changes three features
  d.observe(m, {}, -1, a, 4);
  d.observe(m, a, kEast, b, 4);  // looks one-way to this model: a candidate
  d.observe(m, b, kWest, a, 4);  // the real step back undoes it (and is a candidate itself)
  d.observe(m, a, kEast, b, 4);  // which the next step undoes
  wait(d, m, b, 99);
  for (const auto& sig : d.signatures()) {
    EXPECT_NE(sig.action, kWest) << "the step back is still taken for one-way";
  }
  wait(d, m, b, 2);
  // Only the last step east stayed undone for its window.
  ASSERT_EQ(d.signatures().size(), 1u);
  EXPECT_EQ(d.signatures()[0].action, kEast);
}

TEST(StepDeferral, DrawsAmongEquallyValuedOtherActions) {
  const KeyCorridor m;
  rl_common::Random rng(7);
  StepDeferral d(1000);
  learnThePickup(d, m);
  d.observe(m, {}, -1, kOnKey, 4);
  std::vector<int> counts(4, 0);
  for (int i = 0; i < 300; ++i) ++counts[d.choose(kOnKey, kPickup, {0, 0, 0, 0}, rng)];
  EXPECT_EQ(counts[kPickup], 0);
  for (int a : {kEast, kWest, kWait}) EXPECT_GT(counts[a], 60) << "action " << a;
}

/// The corridor with a door at x == 4 instead of a key: pressing (kPickup) there opens it for
/// good and lights its two lamps, which read 0 everywhere while it is closed.
class DoorCorridor : public rl_common::ModelView {
 public:
  rl_common::StateActionInfo query(const State& s, int a) const override {
    State next = s;
    if (a == kEast) next[0] = std::min(4.0f, s[0] + 1.0f);
    if (a == kWest) next[0] = std::max(0.0f, s[0] - 1.0f);
    if (a == kPickup && s[0] == 4.0f) next[1] = 1.0f;
    next[2] = next[3] = next[1] == 1.0f ? 5.0f : 0.0f;
    rl_common::StateActionInfo info;
    info.known = true;
    for (float v : next) info.factored.push_back({{v, 1.0}});
    return info;
  }
};

/// Where `a` from `s` leads on `m` (these models are deterministic).
State stepOn(const rl_common::ModelView& m, const State& s, int a) {
  State next;
  for (const auto& f : m.query(s, a).factored) next.push_back(f[0].first);
  return next;
}

/// Takes `actions` in turn on `m` from `s`, `d` watching; returns where they led.
State take(StepDeferral& d, const rl_common::ModelView& m, State s,
           const std::vector<int>& actions) {
  for (int a : actions) {
    const State next = stepOn(m, s, a);
    d.observe(m, s, a, next, 4);
    s = next;
  }
  return s;
}

/// Three walks from x == 0 to 4 and back, then to x == 4 (the key corridor: 1 state in 4 on
/// the key).
const std::vector<int> kWalk = [] {
  std::vector<int> v;
  for (int i = 0; i < 3; ++i) {
    v.insert(v.end(), 4, kEast);
    v.insert(v.end(), 4, kWest);
  }
  v.insert(v.end(), 4, kEast);
  return v;
}();

TEST(StepDeferral, ARuleMustSingleOutWhereItsStepHappens) {
  // The door's old values (closed, lamps 0) held in every state before it opened: a rule of
  // them would put pressing off everywhere, so it is not made.
  const DoorCorridor door;
  StepDeferral d(300);
  d.observe(door, {}, -1, {0, 0, 0, 0}, 4);
  State s = take(d, door, {0, 0, 0, 0}, kWalk);
  ASSERT_EQ(s, (State{4, 0, 0, 0}));
  s = take(d, door, s, {kPickup});
  ASSERT_EQ(s, (State{4, 1, 5, 5}));
  wait(d, door, s, 150);
  EXPECT_TRUE(d.signatures().empty()) << "a rule that holds everywhere before its step";
  // The key's old values (lamps at 5) held only on the key: a rule.
  const KeyCorridor key;
  StepDeferral e(300);
  e.observe(key, {}, -1, {0, 0, 0, 0}, 4);
  s = take(e, key, {0, 0, 0, 0}, kWalk);
  s = take(e, key, s, {kWest, kWest, kPickup});
  ASSERT_EQ(s, kHeld);
  wait(e, key, s, 100);
  ASSERT_EQ(e.signatures().size(), 1u);
  EXPECT_EQ(e.signatures()[0].action, kPickup);
}

TEST(StepDeferral, RejectsANegativeStepCount) {
  EXPECT_THROW(StepDeferral(-1), std::invalid_argument);
}

}  // namespace
}  // namespace rl_agent
