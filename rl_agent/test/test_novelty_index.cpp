#include "rl_agent/model/novelty_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rl_common/random.h"

using rl_agent::NoveltyIndex;
using rl_common::State;

TEST(NoveltyIndex, HandComputedDistances) {
  // Two features with ranges 10 and 2; d = 2.
  NoveltyIndex index(2, {0.0f, 0.0f}, {10.0f, 2.0f});
  auto snap = index.snapshot();
  EXPECT_DOUBLE_EQ(snap.novelty({1, 1}, 0), 1.0);  // action never taken
  index.add({2.0f, 0.0f}, 0);
  snap = index.snapshot();
  EXPECT_DOUBLE_EQ(snap.novelty({2, 0}, 0), 0.0);  // visited exactly
  // |5-2|/10 + |1-0|/2 = 0.3 + 0.5 = 0.8, divided by d = 2.
  EXPECT_NEAR(snap.novelty({5, 1}, 0), 0.4, 1e-6);
  EXPECT_DOUBLE_EQ(snap.novelty({2, 0}, 1), 1.0);  // other action
  index.add({6.0f, 1.0f}, 0);
  EXPECT_NEAR(index.snapshot().novelty({5, 1}, 0), 0.05, 1e-6);  // 0.1 / 2
}

TEST(NoveltyIndex, ZeroRangeFeaturesAreSkipped) {
  NoveltyIndex index(1, {0.0f, 3.0f}, {4.0f, 3.0f});
  index.add({0.0f, 3.0f}, 0);
  EXPECT_NEAR(index.snapshot().novelty({2.0f, 3.0f}, 0), 0.25, 1e-6);  // (2/4) / 2
}

TEST(NoveltyIndex, VisitCountsAndVisitedStates) {
  NoveltyIndex index(3, {0.0f}, {10.0f});
  for (int i = 0; i < 3; ++i) index.add({4.0f}, 1);
  index.add({5.0f}, 2);
  const auto snap = index.snapshot();
  EXPECT_EQ(snap.visits({4.0f}, 1), 3);
  EXPECT_EQ(snap.visits({4.0f}, 0), 0);
  EXPECT_EQ(snap.visits({5.0f}, 2), 1);
  EXPECT_TRUE(snap.stateVisited({5.0f}));
  EXPECT_FALSE(snap.stateVisited({6.0f}));
  EXPECT_EQ(snap.size(1), 3u);
}

TEST(NoveltyIndex, AgreesWithBruteForceAcrossBlocks) {
  const int d = 5;
  std::vector<float> lo(d, -1.0f), hi(d, 3.0f);
  NoveltyIndex index(2, lo, hi);
  rl_common::Random rng(4);
  std::vector<State> visited;
  for (int i = 0; i < 1000; ++i) {  // many blocks of different sizes plus a buffer
    State s(d);
    for (auto& x : s) x = static_cast<float>(rng.uniformInt(-1, 3));
    visited.push_back(s);
    index.add(s, 0);
  }
  const auto snap = index.snapshot();
  EXPECT_EQ(snap.size(0), 1000u);
  for (int t = 0; t < 200; ++t) {
    State q(d);
    for (auto& x : q) x = static_cast<float>(rng.uniform(-1.0, 3.0));
    double best = std::numeric_limits<double>::infinity();
    int same = 0;
    for (const auto& v : visited) {
      double dist = 0;
      for (int j = 0; j < d; ++j) dist += std::fabs(q[j] - v[j]) / 4.0;
      best = std::min(best, dist);
    }
    EXPECT_NEAR(snap.novelty(q, 0), best / d, 1e-5);
    const State& v = visited[t];
    for (const auto& w : visited) same += (w == v);
    EXPECT_EQ(snap.visits(v, 0), same);
  }
}

TEST(NoveltyIndex, SnapshotsDoNotChangeAsTheIndexGrows) {
  NoveltyIndex index(1, {0.0f}, {100.0f});
  index.add({0.0f}, 0);
  const auto old = index.snapshot();
  for (int i = 1; i < 200; ++i) index.add({static_cast<float>(i % 100)}, 0);
  EXPECT_EQ(old.size(0), 1u);
  EXPECT_NEAR(old.novelty({50.0f}, 0), 0.5, 1e-6);
  EXPECT_DOUBLE_EQ(index.snapshot().novelty({50.0f}, 0), 0.0);
}

TEST(NoveltyIndex, RejectsBadInput) {
  EXPECT_THROW(NoveltyIndex(0, {0.0f}, {1.0f}), std::invalid_argument);
  EXPECT_THROW(NoveltyIndex(1, {0.0f}, {1.0f, 2.0f}), std::invalid_argument);
  EXPECT_THROW(NoveltyIndex(1, {1.0f}, {0.0f}), std::invalid_argument);
  NoveltyIndex index(2, {0.0f, 0.0f}, {1.0f, 1.0f});
  EXPECT_THROW(index.add({0.0f, 0.0f}, 2), std::invalid_argument);
  EXPECT_THROW(index.add({0.0f}, 0), std::invalid_argument);
}
