// Tests of RandomForest: experience sampling, the combination rules and running accuracies on
// hand-made cases, the KL variance of known distributions, snapshots, and learning a toy
// function.
#include "rl_agent/model/random_forest.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "rl_common/random.h"

namespace rl_agent {
namespace {

void expectDistribution(const Distribution& d, const Distribution& expected) {
  ASSERT_EQ(d.size(), expected.size());
  for (std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_EQ(d[i].first, expected[i].first);
    EXPECT_NEAR(d[i].second, expected[i].second, 1e-12);
  }
}

RandomForest::Config forestConfig(int trees, double expPct, Combination combination) {
  RandomForest::Config c;
  c.numTrees = trees;
  c.expPct = expPct;
  c.combination = combination;
  c.tree.featPct = 0.0;
  return c;
}

std::size_t totalTreeInstances(const RandomForest& f) {
  std::size_t n = 0;
  for (int i = 0; i < f.config().numTrees; ++i)
    n += f.tree(static_cast<std::size_t>(i)).numInstances();
  return n;
}

TEST(RandomForest, CombinationNames) {
  EXPECT_EQ(combinationFromName("average"), Combination::Average);
  EXPECT_EQ(combinationFromName("weighted"), Combination::WeightedAverage);
  EXPECT_EQ(combinationFromName("best"), Combination::Best);
  EXPECT_EQ(combinationFromName("separate"), Combination::Separate);
  EXPECT_THROW(combinationFromName("mean"), std::invalid_argument);
}

// Each tree gets each instance with probability w = 0.55; if none does, one uniform tree does.
// Per tree: Binomial(2000, 0.55 + 0.45^5 / 5) = mean 1107, sd 22; bounds are 5 sd.
TEST(RandomForest, SamplingRate) {
  RandomForest f(forestConfig(5, 0.55, Combination::Average), 17);
  for (int k = 0; k < 2000; ++k) f.addInstance({static_cast<float>(k)}, 0.0f);
  EXPECT_EQ(f.numInstances(), 2000u);
  std::size_t total = 0;
  for (std::size_t i = 0; i < 5; ++i) {
    const std::size_t n = f.tree(i).numInstances();
    EXPECT_GE(n, 996u) << "tree " << i;
    EXPECT_LE(n, 1218u) << "tree " << i;
    total += n;
  }
  EXPECT_GE(total, 2000u);
  // Sum over 5 trees: mean 5537, sd 50.
  EXPECT_NEAR(static_cast<double>(total), 5537.0, 250.0);
}

// With w = 0 every instance goes to exactly one tree (the at-least-one rule), uniformly.
TEST(RandomForest, AtLeastOneTree) {
  RandomForest f(forestConfig(5, 0.0, Combination::Average), 3);
  for (int k = 0; k < 2000; ++k) f.addInstance({static_cast<float>(k)}, 0.0f);
  EXPECT_EQ(totalTreeInstances(f), 2000u);
  for (std::size_t i = 0; i < 5; ++i) {  // Binomial(2000, 0.2): 400 +- 5 * 17.9
    EXPECT_NEAR(static_cast<double>(f.tree(i).numInstances()), 400.0, 90.0) << "tree " << i;
  }
  RandomForest all(forestConfig(3, 1.0, Combination::Average), 3);
  for (int k = 0; k < 50; ++k) all.addInstance({static_cast<float>(k)}, 0.0f);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(all.tree(i).numInstances(), 50u);
}

TEST(RandomForest, BatchSamplingMatchesSingle) {
  RandomForest a(forestConfig(4, 0.55, Combination::Average), 8);
  RandomForest b(forestConfig(4, 0.55, Combination::Average), 8);
  std::vector<std::vector<float>> xs;
  std::vector<float> ys;
  for (int k = 0; k < 100; ++k) {
    xs.push_back({static_cast<float>(k % 7)});
    ys.push_back(static_cast<float>(k % 7 > 3));
    a.addInstance(xs.back(), ys.back());
  }
  b.addInstances(xs, ys);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(a.tree(i).numInstances(), b.tree(i).numInstances());
  }
  EXPECT_EQ(b.numInstances(), 100u);
}

// One instance with w = 0: one tree predicts {1: 1}, the others are empty ({0: 1}), whichever
// tree it was.
TEST(RandomForest, AverageAndVarianceOfOneInstance) {
  RandomForest f(forestConfig(2, 0.0, Combination::Average), 1);
  EXPECT_TRUE(f.addInstance({0}, 1));
  expectDistribution(f.predict({0}), {{0.0f, 0.5}, {1.0f, 0.5}});
  // KL({1:1} || {0:1}) = 1 * ln(1 / 0.01) = ln 100, both ways: D = 2 ln100 / 2 / ln100 = 1.
  EXPECT_NEAR(f.snapshot().variance({0}), 1.0, 1e-12);

  RandomForest g(forestConfig(3, 0.0, Combination::Average), 1);
  g.addInstance({0}, 1);
  expectDistribution(g.predict({0}), {{0.0f, 2.0 / 3.0}, {1.0f, 1.0 / 3.0}});
  // Ordered pairs: 4 of them between the odd tree and an empty one (ln 100 each), 2 between the
  // empty trees (0): D = 4 ln100 / 6 / ln100 = 2/3.
  EXPECT_NEAR(g.snapshot().variance({0}), 2.0 / 3.0, 1e-12);
}

// Accuracies and WEIGHTAVG / BEST by hand. Two trees, w = 0, four instances at x = 0 with
// outputs 1, 1, 0, 0 routed to trees 0, 0, 1, 1 (a seed with that routing is searched for).
// Before each instance (t = 0..3):
//   t=0, y=1: both empty ({0:1}) miss             acc = (0, 0);        tree 0 -> {1:1}
//   t=1, y=1: tree 0 hits, tree 1 misses          acc = (1/2, 0)
//   t=2, y=0: tree 0 misses, tree 1 ({0:1}) hits  acc = (1/3, 1/3);    tree 1 -> {0:1}
//   t=3, y=0: tree 0 misses, tree 1 hits          acc = (1/4, 1/2)
// AVERAGE {0: 1/2, 1: 1/2}; WEIGHTAVG (1/4 {1:1} + 1/2 {0:1}) / (3/4) = {0: 2/3, 1: 1/3};
// BEST tree 1 = {0: 1}.
TEST(RandomForest, CombinationsByHand) {
  const std::vector<float> outputs{1, 1, 0, 0};
  const std::vector<std::size_t> route{0, 0, 1, 1};
  // Trains f; false if the routing differs from `route`.
  auto train = [&](RandomForest& f) {
    for (std::size_t k = 0; k < outputs.size(); ++k) {
      const std::size_t before = f.tree(route[k]).numInstances();
      f.addInstance({0}, outputs[k]);
      if (f.tree(route[k]).numInstances() != before + 1) return false;
    }
    return true;
  };
  std::uint64_t seed = 0;
  bool found = false;
  for (; seed < 1000 && !found; ++seed) {
    RandomForest f(forestConfig(2, 0.0, Combination::Average), seed);
    found = train(f);
  }
  ASSERT_TRUE(found);
  --seed;

  RandomForest avg(forestConfig(2, 0.0, Combination::Average), seed);
  RandomForest weighted(forestConfig(2, 0.0, Combination::WeightedAverage), seed);
  RandomForest best(forestConfig(2, 0.0, Combination::Best), seed);
  ASSERT_TRUE(train(avg));
  ASSERT_TRUE(train(weighted));
  ASSERT_TRUE(train(best));

  for (const RandomForest* f : {&avg, &weighted, &best}) {
    ASSERT_EQ(f->accuracies().size(), 2u);
    EXPECT_NEAR(f->accuracies()[0], 0.25, 1e-12);
    EXPECT_NEAR(f->accuracies()[1], 0.5, 1e-12);
    const auto trees = f->snapshot().treePredictions({0});
    expectDistribution(trees[0], {{1.0f, 1.0}});
    expectDistribution(trees[1], {{0.0f, 1.0}});
    EXPECT_NEAR(f->snapshot().variance({0}), 1.0, 1e-12);
  }
  expectDistribution(avg.predict({0}), {{0.0f, 0.5}, {1.0f, 0.5}});
  expectDistribution(weighted.predict({0}), {{0.0f, 2.0 / 3.0}, {1.0f, 1.0 / 3.0}});
  expectDistribution(best.predict({0}), {{0.0f, 1.0}});
  // Recombined snapshots (--taskcombo) combine the same trees by the other rule.
  expectDistribution(best.snapshot().recombined(Combination::Average).predict({0}),
                     {{0.0f, 0.5}, {1.0f, 0.5}});
  expectDistribution(avg.snapshot().recombined(Combination::WeightedAverage).predict({0}),
                     {{0.0f, 2.0 / 3.0}, {1.0f, 1.0 / 3.0}});
  expectDistribution(avg.snapshot().recombined(Combination::Separate).predict({0}), {{1.0f, 1.0}});
  EXPECT_EQ(avg.snapshot().recombined(Combination::Best).variance({0}), 1.0);
}

// SEPARATE: tree 0 learns every instance and is the prediction.
TEST(RandomForest, SeparatePlansWithTreeZero) {
  RandomForest f(forestConfig(3, 0.0, Combination::Separate), 4);
  for (int k = 0; k < 40; ++k)
    f.addInstance({static_cast<float>(k % 8)}, static_cast<float>(k % 8 > 4));
  EXPECT_EQ(f.tree(0).numInstances(), 40u);
  EXPECT_EQ(f.tree(1).numInstances() + f.tree(2).numInstances(), 0u);  // w = 0
  EXPECT_EQ(f.tree(0).config().featPct, 0.0);
  for (int x = 0; x < 8; ++x) {
    expectDistribution(f.predict({static_cast<float>(x)}), {{x > 4 ? 1.0f : 0.0f, 1.0}});
  }
  // The empty trees disagree with tree 0 where it predicts 1.
  EXPECT_EQ(f.snapshot().variance({1}), 0.0);
  EXPECT_GT(f.snapshot().variance({6}), 0.0);
}

// BAGGED (--taskcombo bagged): the average of the trees other than SEPARATE's planning tree.
TEST(RandomForest, BaggedAveragesTheTreesBesidesThePlanningTree) {
  RandomForest f(forestConfig(3, 1.0, Combination::Separate), 4);
  for (int k = 0; k < 40; ++k)
    f.addInstance({static_cast<float>(k % 8)}, static_cast<float>(k % 8 > 4));
  const RandomForest::Snapshot bagged = f.snapshot().recombined(Combination::Bagged);
  for (int x = 0; x < 8; ++x) {
    const std::vector<Distribution> trees = f.snapshot().treePredictions({static_cast<float>(x)});
    std::map<float, double> mean;
    for (std::size_t i = 1; i < trees.size(); ++i) {
      for (const auto& [v, p] : trees[i]) mean[v] += p / 2.0;
    }
    expectDistribution(bagged.predict({static_cast<float>(x)}),
                       Distribution(mean.begin(), mean.end()));
  }
  // Tree 0 does not count: with w = 0 only it learns, and the bagged trees' empty leaves
  // predict 0 where it predicts 1.
  RandomForest g(forestConfig(3, 0.0, Combination::Separate), 4);
  for (int k = 0; k < 40; ++k)
    g.addInstance({static_cast<float>(k % 8)}, static_cast<float>(k % 8 > 4));
  expectDistribution(g.predict({6}), {{1.0f, 1.0}});
  expectDistribution(g.snapshot().recombined(Combination::Bagged).predict({6}), {{0.0f, 1.0}});
  expectDistribution(g.snapshot().recombined(Combination::Average).predict({6}),
                     {{0.0f, 2.0 / 3.0}, {1.0f, 1.0 / 3.0}});
  // Every tree of a forest without a planning tree is bagged: the plain average.
  RandomForest a(forestConfig(3, 0.5, Combination::Average), 4);
  for (int k = 0; k < 40; ++k)
    a.addInstance({static_cast<float>(k % 8)}, static_cast<float>(k % 8 > 4));
  for (int x = 0; x < 8; ++x) {
    expectDistribution(
        a.snapshot().recombined(Combination::Bagged).predict({static_cast<float>(x)}),
        a.predict({static_cast<float>(x)}));
  }
  EXPECT_EQ(combinationFromName("bagged"), Combination::Bagged);
}

TEST(RandomForest, KlDivergenceByHand) {
  // 0.5 ln(0.5/1) + 0.5 ln(0.5/0.01) = 0.5 ln 25 = ln 5 (the epsilon for the missing 1).
  EXPECT_NEAR(klDivergence({{0.0f, 0.5}, {1.0f, 0.5}}, {{0.0f, 1.0}}), std::log(5.0), 1e-12);
  // No epsilon needed the other way: 1 ln(1/0.5).
  EXPECT_NEAR(klDivergence({{0.0f, 1.0}}, {{0.0f, 0.5}, {1.0f, 0.5}}), std::log(2.0), 1e-12);
  EXPECT_NEAR(klDivergence({{0.0f, 0.5}, {1.0f, 0.5}}, {{0.0f, 0.25}, {1.0f, 0.75}}),
              0.5 * std::log(2.0) + 0.5 * std::log(2.0 / 3.0), 1e-12);
  EXPECT_NEAR(klDivergence({{1.0f, 1.0}}, {{0.0f, 1.0}}), std::log(100.0), 1e-12);
  EXPECT_EQ(klDivergence({{2.0f, 0.3}, {3.0f, 0.7}}, {{2.0f, 0.3}, {3.0f, 0.7}}), 0.0);
  // Zero-probability outcomes of the first argument do not count.
  EXPECT_NEAR(klDivergence({{0.0f, 0.0}, {1.0f, 1.0}}, {{1.0f, 1.0}}), 0.0, 1e-15);
  EXPECT_THROW(klDivergence({{0.0f, 1.5}}, {{0.0f, 1.0}}), std::invalid_argument);
  EXPECT_THROW(klDivergence({{0.0f, 1.0}}, {{0.0f, -0.5}}), std::invalid_argument);
}

TEST(RandomForest, VarianceZeroWhenTreesAgree) {
  // w = 1 and featPct = 0: identical trees.
  RandomForest f(forestConfig(4, 1.0, Combination::Average), 2);
  for (int k = 0; k < 30; ++k) {
    f.addInstance({static_cast<float>(k % 5), 1.0f}, static_cast<float>(k % 3));
  }
  for (int x = 0; x < 5; ++x) EXPECT_EQ(f.snapshot().variance({float(x), 1.0f}), 0.0);
  RandomForest one(forestConfig(1, 0.55, Combination::Average), 2);
  one.addInstance({0}, 1);
  EXPECT_EQ(one.snapshot().variance({0}), 0.0);
}

// output = (x0 > 3), x1 noise: every tree ends up exact wherever it has data, so the forest
// predicts the function with certainty and the trees agree.
TEST(RandomForest, LearnsToyFunction) {
  RandomForest::Config c;  // defaults: 5 trees, w 0.55, featPct 0.2, AVERAGE
  RandomForest f(c, 7);
  rl_common::Random rng(99);
  for (int k = 0; k < 600; ++k) {
    const float x0 = static_cast<float>(rng.uniformInt(0, 9));
    const float x1 = static_cast<float>(rng.uniformInt(0, 4));
    f.addInstance({x0, x1}, x0 > 3 ? 1.0f : 0.0f);
  }
  const RandomForest::Snapshot s = f.snapshot();
  for (int x0 = 0; x0 < 10; ++x0) {
    for (int x1 = 0; x1 < 5; ++x1) {
      const std::vector<float> x{float(x0), float(x1)};
      const float truth = x0 > 3 ? 1.0f : 0.0f;
      EXPECT_NEAR(probabilityOf(s.predict(x), truth), 1.0, 1e-12) << x0 << "," << x1;
      EXPECT_NEAR(s.variance(x), 0.0, 1e-12);
    }
  }
}

TEST(RandomForest, SnapshotUnchangedWhileLearning) {
  RandomForest f(forestConfig(3, 0.55, Combination::Average), 5);
  for (int k = 0; k < 60; ++k)
    f.addInstance({static_cast<float>(k % 6)}, static_cast<float>(k % 2));
  const RandomForest::Snapshot old = f.snapshot();
  std::vector<Distribution> before;
  for (int x = 0; x < 6; ++x) before.push_back(old.predict({float(x)}));
  const double var = old.variance({2});
  for (int k = 0; k < 60; ++k) f.addInstance({static_cast<float>(k % 6)}, 7.0f);
  bool differs = false;
  for (int x = 0; x < 6; ++x) {
    EXPECT_EQ(old.predict({float(x)}), before[static_cast<std::size_t>(x)]);
    differs = differs || f.predict({float(x)}) != before[static_cast<std::size_t>(x)];
  }
  EXPECT_TRUE(differs);
  EXPECT_EQ(old.variance({2}), var);
  EXPECT_EQ(old.numTrees(), 3u);
}

TEST(RandomForest, SameSeedSameForest) {
  RandomForest::Config c;
  auto grow = [&c](std::uint64_t seed) {
    RandomForest f(c, seed);
    rl_common::Random rng(1);
    for (int k = 0; k < 200; ++k) {
      const float a = static_cast<float>(rng.uniformInt(0, 5));
      const float b = static_cast<float>(rng.uniformInt(0, 5));
      f.addInstance({a, b}, static_cast<float>((a + b > 5) + (b == 2)));
    }
    std::string s;
    for (std::size_t i = 0; i < 5; ++i) s += f.tree(i).snapshot().describe() + "\n";
    return s;
  };
  EXPECT_EQ(grow(3), grow(3));
  EXPECT_NE(grow(3), grow(4));
}

TEST(RandomForest, RejectsBadInput) {
  RandomForest::Config c;
  c.numTrees = 0;
  EXPECT_THROW(RandomForest(c, 1), std::invalid_argument);
  c = RandomForest::Config{};
  c.expPct = 1.2;
  EXPECT_THROW(RandomForest(c, 1), std::invalid_argument);
  c = RandomForest::Config{};
  c.tree.featPct = -0.2;
  EXPECT_THROW(RandomForest(c, 1), std::invalid_argument);

  RandomForest f(RandomForest::Config{}, 1);
  f.addInstance({1, 2}, 0);
  try {
    f.addInstance({1}, 0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("RandomForest::addInstance():", 0), 0u) << e.what();
  }
  EXPECT_THROW(f.addInstances({{1, 2}}, {}), std::invalid_argument);
  EXPECT_THROW(f.addInstances({{1, 2}, {1, 2, 3}}, {0, 0}), std::invalid_argument);
  EXPECT_THROW(f.addInstance({1, 2}, std::nanf("")), std::invalid_argument);
  EXPECT_EQ(f.numInstances(), 1u);  // nothing was learnt from the bad calls
  f.addInstances({{3, 4}}, {1});
  EXPECT_EQ(f.numInstances(), 2u);
}

}  // namespace
}  // namespace rl_agent
