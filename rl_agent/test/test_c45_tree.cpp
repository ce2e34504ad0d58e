// Tests of C45Tree: hand-computed splits and leaves, the BUILD_ON_ERROR rule, incremental ==
// batch, immutable shared snapshots, seeding and input validation.
#include "rl_agent/model/c45_tree.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "rl_common/random.h"

namespace rl_agent {
namespace {

C45Tree::Config deterministic() {
  C45Tree::Config c;
  c.featPct = 0.0;
  return c;
}

C45Tree batchTree(const std::vector<std::vector<float>>& x, const std::vector<float>& y,
                  const C45Tree::Config& config = deterministic(), std::uint64_t seed = 1) {
  C45Tree t(config, seed);
  t.addInstances(x, y);
  return t;
}

void expectDistribution(const Distribution& d, const Distribution& expected) {
  ASSERT_EQ(d.size(), expected.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d[i].first, expected[i].first);
    EXPECT_NEAR(d[i].second, expected[i].second, 1e-12);
  }
}

TEST(C45Tree, EmptyTreePredictsZero) {
  C45Tree t(deterministic(), 1);
  expectDistribution(t.predict({1.0f, 2.0f}), {{0.0f, 1.0}});
  EXPECT_TRUE(t.snapshot().empty());
  EXPECT_EQ(t.snapshot().numNodes(), 0u);
  EXPECT_EQ(t.numInstances(), 0u);
}

// One input, values 1, 2, 3; output 1 only at x == 2. By hand (entropies in bits, H(T) =
// H(1/3, 2/3) = 0.918): CUT x<=1 and CUT x<=2 each leave one side pure and the other at 1 bit,
// gain 0.918 - 4/6 = 0.252, split info 0.918, GR 0.274; ONLY x==2 separates perfectly, GR 1
// (x==1 is not a candidate: ONLY skips the minimum; 3 is the maximum).
TEST(C45Tree, OnlySplitChosenByGainRatio) {
  const C45Tree t = batchTree({{1}, {1}, {2}, {2}, {3}, {3}}, {0, 0, 1, 1, 0, 0});
  EXPECT_EQ(t.snapshot().describe(), "(x0 == 2 ? {1: 1} : {0: 1})");
  expectDistribution(t.predict({2.0f}), {{1.0f, 1.0}});
  expectDistribution(t.predict({3.0f}), {{0.0f, 1.0}});
  expectDistribution(t.predict({7.0f}), {{0.0f, 1.0}});  // unseen values follow x != 2
  EXPECT_EQ(t.snapshot().numNodes(), 3u);
  EXPECT_EQ(t.snapshot().depth(), 1u);
}

// Two inputs, six instances a..f = (0,0)0 (0,1)0 (1,0)0 (1,1)1 (2,1)1 (2,0)1. At the root, by
// hand: CUT x0<=0 gives L={a,b} pure, R=(1 zero, 3 ones): gain = 1 - 4/6*0.811 = 0.459, split
// info H(1/3,2/3) = 0.918, GR = 0.5 exactly; CUT x0<=1 is the mirror image, also 0.5 (tie: the
// first found, x0<=0, wins); ONLY x0==1 has gain 0; CUT x1<=0 gives (2,1)|(1,2), GR 0.082.
// Under x0>0: CUT x0<=1 and CUT x1<=0 tie at GR 0.311 (x0 first); then x1 separates c from d.
TEST(C45Tree, HandComputedTreeWithTies) {
  const C45Tree t = batchTree({{0, 0}, {0, 1}, {1, 0}, {1, 1}, {2, 1}, {2, 0}}, {0, 0, 0, 1, 1, 1});
  EXPECT_EQ(t.snapshot().describe(),
            "(x0 <= 0 ? {0: 1} : (x0 <= 1 ? (x1 <= 0 ? {0: 1} : {1: 1}) : {1: 1}))");
  EXPECT_EQ(t.snapshot().numNodes(), 7u);
  EXPECT_EQ(t.snapshot().depth(), 3u);
  expectDistribution(t.predict({1.0f, 0.0f}), {{0.0f, 1.0}});
  expectDistribution(t.predict({1.0f, 1.0f}), {{1.0f, 1.0}});
}

// Identical inputs cannot be split: the leaf predicts the output frequencies.
TEST(C45Tree, MixedLeafGivesFrequencies) {
  const C45Tree t = batchTree({{5, 1}, {5, 1}, {5, 1}, {5, 1}, {5, 1}}, {1, 1, 1, 2, -3});
  EXPECT_EQ(t.snapshot().numNodes(), 1u);
  expectDistribution(t.predict({5.0f, 1.0f}), {{-3.0f, 0.2}, {1.0f, 0.6}, {2.0f, 0.2}});
  expectDistribution(t.predict({0.0f, 0.0f}), {{-3.0f, 0.2}, {1.0f, 0.6}, {2.0f, 0.2}});
}

// x=0: outputs 0,0,1; x=1: outputs 1,1,0. The only candidate, CUT x0<=0, has gain
// 1 - H(1/3) = 0.082 bits and split info 1, so GR = 0.0817: a split above minGainRatio 0.08, a
// mixed leaf below 0.1.
TEST(C45Tree, MinGainRatioMakesLeaf) {
  const std::vector<std::vector<float>> x{{0}, {0}, {0}, {1}, {1}, {1}};
  const std::vector<float> y{0, 0, 1, 1, 1, 0};
  C45Tree::Config c = deterministic();
  c.minGainRatio = 0.1;
  EXPECT_EQ(batchTree(x, y, c).snapshot().describe(), "{0: 0.5, 1: 0.5}");
  c.minGainRatio = 0.08;
  EXPECT_EQ(batchTree(x, y, c).snapshot().describe(),
            "(x0 <= 0 ? {0: 0.666667, 1: 0.333333} : {0: 0.333333, 1: 0.666667})");
}

TEST(C45Tree, OutputsCompareByValue) {
  // -0 and 0 are the same class; 0.5 is not 0.
  const C45Tree t = batchTree({{0}, {0}, {1}}, {0.0f, -0.0f, 0.5f});
  expectDistribution(t.predict({0.0f}), {{0.0f, 1.0}});
  expectDistribution(t.predict({1.0f}), {{0.5f, 1.0}});
}

// BUILD_ON_ERROR with threshold 0.75: an instance whose output has probability >= 0.75 at its
// leaf is only stored; one below rebuilds (and the stored instances then count).
TEST(C45Tree, RebuildThreshold) {
  C45Tree t(deterministic(), 1);
  EXPECT_TRUE(t.addInstance({5}, 1));   // the first instance builds the tree
  EXPECT_FALSE(t.addInstance({5}, 1));  // P(1) = 1
  EXPECT_FALSE(t.addInstance({5}, 1));
  EXPECT_TRUE(t.addInstance({5}, 0));  // P(0) = 0 < 0.75
  expectDistribution(t.predict({5}), {{0.0f, 0.25}, {1.0f, 0.75}});

  const C45Tree::Snapshot before = t.snapshot();
  EXPECT_FALSE(t.addInstance({5}, 1));  // P(1) = 0.75: not below the threshold
  expectDistribution(t.predict({5}), {{0.0f, 0.25}, {1.0f, 0.75}});
  EXPECT_EQ(t.snapshot().sharedNodes(before), 1u);  // the very same tree
  EXPECT_EQ(t.numInstances(), 5u);

  EXPECT_TRUE(t.addInstance({5}, 0));  // P(0) = 0.25
  // 6 instances: 2 zeros, 4 ones (the unnoticed 1 counts now).
  expectDistribution(t.predict({5}), {{0.0f, 2.0 / 6.0}, {1.0f, 4.0 / 6.0}});
  EXPECT_EQ(t.snapshot().sharedNodes(before), 0u);
}

TEST(C45Tree, CustomThreshold) {
  C45Tree::Config c = deterministic();
  c.rebuildThreshold = 0.5;
  C45Tree t(c, 1);
  t.addInstances({{1}, {1}, {1}, {1}}, {1, 1, 1, 0});  // leaf {0: .25, 1: .75}
  EXPECT_FALSE(t.addInstance({1}, 1));
  EXPECT_TRUE(t.addInstance({1}, 0));  // 0.25 < 0.5
}

// addInstances checks every new instance against the old tree and rebuilds at most once.
TEST(C45Tree, BatchAddRebuildsOnce) {
  C45Tree t(deterministic(), 1);
  t.addInstances({{0}, {1}}, {0, 1});
  EXPECT_EQ(t.snapshot().describe(), "(x0 <= 0 ? {0: 1} : {1: 1})");
  EXPECT_FALSE(t.addInstances({{0}, {1}, {0}}, {0, 1, 0}));  // all predicted
  EXPECT_EQ(t.numInstances(), 5u);
  EXPECT_TRUE(t.addInstances({{0}, {2}}, {0, 2}));  // x=2 -> 2 is wrong
  EXPECT_EQ(t.snapshot().describe(), "(x0 <= 0 ? {0: 1} : (x0 <= 1 ? {1: 1} : {2: 1}))");
  EXPECT_FALSE(t.addInstances({}, {}));
}

// The incremental rebuild (reusing unchanged subtrees) gives exactly the tree a batch build
// grows from the same instances.
TEST(C45Tree, IncrementalEqualsBatch) {
  rl_common::Random rng(11);
  std::vector<std::vector<float>> xs;
  std::vector<float> ys;
  C45Tree inc(deterministic(), 1);
  std::string lastBatch;
  int rebuilds = 0;
  for (int k = 0; k < 300; ++k) {
    std::vector<float> x{static_cast<float>(rng.uniformInt(0, 4)),
                         static_cast<float>(rng.uniformInt(0, 4)),
                         static_cast<float>(rng.uniformInt(0, 2))};
    float y = (x[0] + x[1] > 4.0f) ? 1.0f : 0.0f;
    if (x[2] == 2.0f && x[0] == 0.0f) y = 2.0f;
    if (rng.uniform() < 0.05) y = 3.0f;  // some noise: mixed leaves and late changes
    xs.push_back(x);
    ys.push_back(y);
    const std::string before = inc.snapshot().describe();
    const bool changed = inc.addInstance(x, y);
    if (changed) {
      ++rebuilds;
      lastBatch = batchTree(xs, ys).snapshot().describe();
      ASSERT_EQ(inc.snapshot().describe(), lastBatch) << "after instance " << k;
    } else {
      ASSERT_EQ(inc.snapshot().describe(), before) << "after instance " << k;
    }
  }
  EXPECT_GT(rebuilds, 10);
  EXPECT_GT(inc.snapshot().numNodes(), 5u);
}

// Snapshots are immutable; a rebuild shares every subtree it does not re-grow.
TEST(C45Tree, SnapshotsStayValidAndShareSubtrees) {
  // x0 in {0,1}, x1 in 0..3, twice each; y = 0/1 (x0 = 0) or 2/3 (x0 = 1) by x1 <= 1.
  std::vector<std::vector<float>> xs;
  std::vector<float> ys;
  for (int rep = 0; rep < 2; ++rep) {
    for (int x0 = 0; x0 < 2; ++x0) {
      for (int x1 = 0; x1 < 4; ++x1) {
        xs.push_back({static_cast<float>(x0), static_cast<float>(x1)});
        ys.push_back(static_cast<float>(2 * x0 + (x1 <= 1 ? 0 : 1)));
      }
    }
  }
  C45Tree t(deterministic(), 1);
  t.addInstances(xs, ys);
  const C45Tree::Snapshot s1 = t.snapshot();
  const std::string tree1 = "(x0 <= 0 ? (x1 <= 1 ? {0: 1} : {1: 1}) : (x1 <= 1 ? {2: 1} : {3: 1}))";
  ASSERT_EQ(s1.describe(), tree1);

  // A new output at (1, 3): only the x0 = 1 side, and there only the x1 > 1 side, grows.
  EXPECT_TRUE(t.addInstance({1, 3}, 4));
  const C45Tree::Snapshot s2 = t.snapshot();
  EXPECT_EQ(s2.describe(),
            "(x0 <= 0 ? (x1 <= 1 ? {0: 1} : {1: 1}) : (x1 <= 1 ? {2: 1} : "
            "(x1 <= 2 ? {3: 1} : {3: 0.666667, 4: 0.333333})))");
  EXPECT_EQ(s2.numNodes(), 9u);
  // Shared: the whole x0 <= 0 subtree (3 nodes) and the {2: 1} leaf.
  EXPECT_EQ(s2.sharedNodes(s1), 4u);
  EXPECT_EQ(s1.sharedNodes(s2), 4u);
  // The old snapshot still predicts the old tree.
  EXPECT_EQ(s1.describe(), tree1);
  expectDistribution(s1.predict({1, 3}), {{3.0f, 1.0}});
  expectDistribution(s2.predict({1, 3}), {{3.0f, 2.0 / 3.0}, {4.0f, 1.0 / 3.0}});
  // The new tree is the one a batch build grows from all 17 instances.
  xs.push_back({1, 3});
  ys.push_back(4);
  EXPECT_EQ(batchTree(xs, ys).snapshot().describe(), s2.describe());
}

TEST(C45Tree, OldSnapshotUnchangedWhileLearning) {
  rl_common::Random rng(5);
  C45Tree t(C45Tree::Config{}, 3);  // default featPct 0.2
  auto sample = [&rng] {
    return std::vector<float>{static_cast<float>(rng.uniformInt(0, 9)),
                              static_cast<float>(rng.uniformInt(0, 3))};
  };
  for (int k = 0; k < 100; ++k) {
    const auto x = sample();
    t.addInstance(x, x[0] > 3 ? 1.0f : static_cast<float>(x[1] == 2));
  }
  const C45Tree::Snapshot old = t.snapshot();
  const std::string text = old.describe();
  std::vector<Distribution> predictions;
  for (int a = 0; a < 10; ++a) {
    for (int b = 0; b < 4; ++b) predictions.push_back(old.predict({float(a), float(b)}));
  }
  for (int k = 0; k < 300; ++k) {
    const auto x = sample();
    t.addInstance(x, static_cast<float>(rng.uniformInt(0, 3)));  // a different function
  }
  EXPECT_NE(t.snapshot().describe(), text);
  EXPECT_EQ(old.describe(), text);
  std::size_t i = 0;
  for (int a = 0; a < 10; ++a) {
    for (int b = 0; b < 4; ++b) EXPECT_EQ(old.predict({float(a), float(b)}), predictions[i++]);
  }
}

// A planner thread reads an old snapshot while the learner thread rebuilds the tree (and
// releases nodes the snapshot still shares).
TEST(C45Tree, SnapshotReadFromAnotherThread) {
  rl_common::Random rng(8);
  C45Tree t(C45Tree::Config{}, 4);
  auto sample = [&rng] {
    return std::vector<float>{static_cast<float>(rng.uniformInt(0, 9)),
                              static_cast<float>(rng.uniformInt(0, 9))};
  };
  for (int k = 0; k < 100; ++k) {
    const auto x = sample();
    t.addInstance(x, static_cast<float>(x[0] > 4));
  }
  const C45Tree::Snapshot s = t.snapshot();
  std::vector<Distribution> expected;
  for (int a = 0; a < 10; ++a) expected.push_back(s.predict({float(a), 1.0f}));
  std::atomic<bool> stop{false};
  std::atomic<int> mismatches{0}, reads{0};
  std::thread reader([&] {
    const C45Tree::Snapshot mine = s;
    do {
      for (int a = 0; a < 10; ++a) {
        if (mine.predict({float(a), 1.0f}) != expected[static_cast<std::size_t>(a)]) ++mismatches;
      }
      ++reads;
    } while (!stop);
  });
  for (int k = 0; k < 400; ++k) t.addInstance(sample(), static_cast<float>(rng.uniformInt(0, 2)));
  stop = true;
  reader.join();
  EXPECT_EQ(mismatches.load(), 0);
  EXPECT_GT(reads.load(), 0);
}

TEST(C45Tree, CopiesLearnIndependently) {
  C45Tree a(deterministic(), 1);
  a.addInstances({{0}, {1}}, {0, 1});
  C45Tree b = a;
  b.addInstance({2}, 2);
  EXPECT_EQ(a.numInstances(), 2u);
  EXPECT_EQ(b.numInstances(), 3u);
  EXPECT_EQ(a.snapshot().describe(), "(x0 <= 0 ? {0: 1} : {1: 1})");
  a.addInstance({2}, 5);
  expectDistribution(a.predict({2}), {{5.0f, 1.0}});
  expectDistribution(b.predict({2}), {{2.0f, 1.0}});
}

// featPct > 0 draws from the tree's own seeded source: same seed, same tree.
TEST(C45Tree, SameSeedSameTree) {
  rl_common::Random rng(2);
  std::vector<std::vector<float>> xs;
  std::vector<float> ys;
  for (int k = 0; k < 200; ++k) {
    xs.push_back({static_cast<float>(rng.uniformInt(0, 5)),
                  static_cast<float>(rng.uniformInt(0, 5)),
                  static_cast<float>(rng.uniformInt(0, 5))});
    ys.push_back(static_cast<float>((static_cast<int>(xs.back()[0]) + 2 * xs.back()[2] > 6) +
                                    (xs.back()[1] == 3)));
  }
  C45Tree::Config c;
  c.featPct = 0.5;
  auto grow = [&](std::uint64_t seed) {
    C45Tree t(c, seed);
    for (std::size_t k = 0; k < xs.size(); ++k) t.addInstance(xs[k], ys[k]);
    return t.snapshot().describe();
  };
  EXPECT_EQ(grow(9), grow(9));
  std::set<std::string> trees;
  for (std::uint64_t seed = 0; seed < 6; ++seed) trees.insert(grow(seed));
  EXPECT_GT(trees.size(), 1u);  // the skipping really depends on the seed
}

// featPct = 1 skips every candidate: a single (mixed) leaf.
TEST(C45Tree, FeatPctOneGivesLeaf) {
  C45Tree::Config c;
  c.featPct = 1.0;
  const C45Tree t = batchTree({{0}, {1}, {2}, {3}}, {0, 0, 1, 1}, c);
  EXPECT_EQ(t.snapshot().describe(), "{0: 0.5, 1: 0.5}");
}

// A staircase grows a chain as deep as the data; building, predicting and releasing it must
// not depend on recursion.
TEST(C45Tree, DeepTree) {
  std::vector<std::vector<float>> xs;
  std::vector<float> ys;
  const int n = 1500;
  for (int i = 0; i < n; ++i) {
    xs.push_back({static_cast<float>(i)});
    ys.push_back(static_cast<float>(i % 2));
  }
  {
    const C45Tree t = batchTree(xs, ys);
    EXPECT_GT(t.snapshot().depth(), 100u);
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(probabilityOf(t.predict(xs[i]), ys[i]), 1.0) << i;
    }
  }
}

TEST(C45Tree, RejectsBadInput) {
  C45Tree t(deterministic(), 1);
  EXPECT_THROW(t.addInstance({}, 1), std::invalid_argument);
  t.addInstance({1, 2}, 1);
  EXPECT_THROW(t.addInstance({1, 2, 3}, 1), std::invalid_argument);
  EXPECT_THROW(t.addInstance({1, std::nanf("")}, 1), std::invalid_argument);
  EXPECT_THROW(t.addInstance({1, 2}, std::nanf("")), std::invalid_argument);
  EXPECT_THROW(t.addInstances({{1, 2}}, {1, 2}), std::invalid_argument);
  // A bad instance in a batch leaves the tree untouched.
  EXPECT_THROW(t.addInstances({{1, 2}, {1}}, {1, 2}), std::invalid_argument);
  EXPECT_EQ(t.numInstances(), 1u);
  EXPECT_THROW(t.predict({1}), std::invalid_argument);
  try {
    t.addInstance({1}, 0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("C45Tree::addInstance():", 0), 0u) << e.what();
  }
  C45Tree::Config bad;
  bad.featPct = 1.5;
  EXPECT_THROW(C45Tree(bad, 1), std::invalid_argument);
  bad = C45Tree::Config{};
  bad.rebuildThreshold = -0.1;
  EXPECT_THROW(C45Tree(bad, 1), std::invalid_argument);
}

}  // namespace
}  // namespace rl_agent
