// Tests of the shared input table: trees, forests and the factored model keeping their inputs
// in one C45Tree::InputTable grow exactly the trees they grow with storage of their own, and
// bad rows are rejected without touching the tree.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "rl_agent/model/c45_tree.h"
#include "rl_agent/model/factored_model.h"
#include "rl_agent/model/random_forest.h"
#include "rl_common/random.h"

namespace rl_agent {
namespace {

using Table = C45Tree::InputTable;

// Few distinct values, so that ties between equal inputs (broken by order of arrival) abound.
std::vector<float> sampleInput(rl_common::Random& rng, std::size_t n) {
  std::vector<float> x(n);
  for (float& v : x) v = static_cast<float>(rng.uniformInt(0, 3));
  return x;
}

float label(const std::vector<float>& x, rl_common::Random& rng) {
  float y = (x[0] + x[1] > 3.0f) ? 1.0f : 0.0f;
  if (x[2] == 2.0f) y = 2.0f;
  if (rng.uniform() < 0.1) y = static_cast<float>(rng.uniformInt(0, 3));  // noise
  return y;
}

TEST(SharedInputs, TableAppendsAndValidates) {
  Table t;
  EXPECT_EQ(t.size(), 0u);
  EXPECT_EQ(t.numInputs(), 0u);
  EXPECT_THROW(t.append({}), std::invalid_argument);
  EXPECT_EQ(t.append({1, 2}), 0u);
  EXPECT_EQ(t.append({3, 4}), 1u);
  EXPECT_EQ(t.numInputs(), 2u);
  EXPECT_EQ(t.row(1), (std::vector<float>{3, 4}));
  EXPECT_THROW(t.append({1}), std::invalid_argument);
  EXPECT_THROW(t.append({1, std::nanf("")}), std::invalid_argument);
  EXPECT_THROW(t.row(2), std::out_of_range);
  EXPECT_EQ(t.size(), 2u);
}

// Several trees on one table, each getting a random share of the rows (as a forest's trees
// do), against one standalone tree each: same changes, same trees, after every instance.
TEST(SharedInputs, TreesOnASharedTableEqualStandaloneTrees) {
  const int numTrees = 4;
  C45Tree::Config config;  // featPct 0.2: the split skipping must draw the same numbers
  auto table = std::make_shared<Table>();
  std::vector<C45Tree> shared, own;
  for (int i = 0; i < numTrees; ++i) {
    shared.emplace_back(config, 10 + i, table);
    own.emplace_back(config, 10 + i);
  }
  rl_common::Random rng(4);
  for (int k = 0; k < 600; ++k) {
    const std::vector<float> x = sampleInput(rng, 4);
    const std::uint32_t row = table->append(x);
    for (std::size_t i = 0; i < shared.size(); ++i) {
      if (rng.uniform() >= 0.55) continue;
      const float y = label(x, rng) + static_cast<float>(i);
      const bool changedShared = shared[i].addRows({row}, {y});
      ASSERT_EQ(changedShared, own[i].addInstance(x, y)) << "tree " << i << ", row " << k;
      ASSERT_EQ(shared[i].snapshot().describe(), own[i].snapshot().describe())
          << "tree " << i << ", row " << k;
    }
  }
  for (std::size_t i = 0; i < shared.size(); ++i) {
    EXPECT_EQ(shared[i].numInstances(), own[i].numInstances());
    EXPECT_GT(shared[i].snapshot().numNodes(), 5u);
  }
  EXPECT_EQ(table->size(), 600u);
}

// Batches of rows rebuild at most once, as batches of inputs do.
TEST(SharedInputs, BatchOfRowsEqualsBatchOfInputs) {
  auto table = std::make_shared<Table>();
  C45Tree shared(C45Tree::Config{}, 3, table), own(C45Tree::Config{}, 3);
  rl_common::Random rng(9);
  for (int batch = 0; batch < 30; ++batch) {
    std::vector<std::vector<float>> xs;
    std::vector<std::uint32_t> rows;
    std::vector<float> ys;
    for (int k = 0; k < 7; ++k) {
      xs.push_back(sampleInput(rng, 3));
      table->append(sampleInput(rng, 3));  // a row for someone else
      rows.push_back(table->append(xs.back()));
      ys.push_back(label(xs.back(), rng));
    }
    ASSERT_EQ(shared.addRows(rows, ys), own.addInstances(xs, ys)) << "batch " << batch;
    ASSERT_EQ(shared.snapshot().describe(), own.snapshot().describe()) << "batch " << batch;
  }
}

TEST(SharedInputs, AddInstanceAppendsToTheSharedTable) {
  auto table = std::make_shared<Table>();
  C45Tree t(C45Tree::Config{}, 1, table);
  table->append({5, 5});
  t.addInstance({0, 1}, 2);
  EXPECT_EQ(table->size(), 2u);
  EXPECT_EQ(&t.inputs(), table.get());
  EXPECT_EQ(t.numInstances(), 1u);
  // Copies of a tree on a shared table keep using it.
  C45Tree copy = t;
  copy.addInstance({1, 1}, 3);
  EXPECT_EQ(table->size(), 3u);
  EXPECT_EQ(t.numInstances(), 1u);
  EXPECT_EQ(copy.numInstances(), 2u);
}

TEST(SharedInputs, RejectsRowsOutOfOrder) {
  auto table = std::make_shared<Table>();
  for (int k = 0; k < 4; ++k) table->append({static_cast<float>(k)});
  C45Tree t(C45Tree::Config{}, 1, table);
  t.addRows({1}, {0});
  const std::string before = t.snapshot().describe();
  EXPECT_THROW(t.addRows({1}, {1}), std::invalid_argument);        // already added
  EXPECT_THROW(t.addRows({0}, {1}), std::invalid_argument);        // older than the last
  EXPECT_THROW(t.addRows({4}, {1}), std::invalid_argument);        // not in the table
  EXPECT_THROW(t.addRows({3, 2}, {1, 1}), std::invalid_argument);  // not ascending
  EXPECT_THROW(t.addRows({2}, {std::nanf("")}), std::invalid_argument);
  EXPECT_THROW(t.addRows({2}, {1, 2}), std::invalid_argument);
  EXPECT_EQ(t.numInstances(), 1u);
  EXPECT_EQ(t.snapshot().describe(), before);
  EXPECT_TRUE(t.addRows({2, 3}, {1, 1}));
  EXPECT_EQ(t.snapshot().describe(), "(x0 <= 1 ? {0: 1} : {1: 1})");
}

// A forest's tree equals a standalone tree on the same instances and seed; a forest on a
// table other forests append to equals one on its own table.
TEST(SharedInputs, ForestsOnASharedTableEqualStandaloneForests) {
  RandomForest::Config single;
  single.numTrees = 1;
  single.expPct = 1.0;
  RandomForest one(single, 6);
  C45Tree reference(single.tree, rl_common::Random::deriveSeed(6, "c45_tree", 0));

  RandomForest::Config config;  // 5 trees, w 0.55, featPct 0.2
  auto table = std::make_shared<Table>();
  RandomForest a(config, 21, table), b(config, 22, table);
  RandomForest ownA(config, 21), ownB(config, 22);
  rl_common::Random rng(13);
  for (int k = 0; k < 400; ++k) {
    const std::vector<float> x = sampleInput(rng, 4);
    const float y = label(x, rng);
    ASSERT_EQ(one.addInstance(x, y), reference.addInstance(x, y)) << k;
    ASSERT_EQ(one.tree(0).snapshot().describe(), reference.snapshot().describe()) << k;

    const std::uint32_t row = table->append(x);
    ASSERT_EQ(a.addRow(row, y), ownA.addInstance(x, y)) << k;
    ASSERT_EQ(b.addInstance(x, y + 1.0f), ownB.addInstance(x, y + 1.0f)) << k;
  }
  EXPECT_EQ(table->size(), 800u);
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_EQ(a.tree(i).snapshot().describe(), ownA.tree(i).snapshot().describe()) << i;
    EXPECT_EQ(b.tree(i).snapshot().describe(), ownB.tree(i).snapshot().describe()) << i;
  }
  EXPECT_EQ(a.accuracies(), ownA.accuracies());
  EXPECT_EQ(b.accuracies(), ownB.accuracies());
  EXPECT_THROW(a.addRow(0, 1.0f), std::invalid_argument);    // already learned
  EXPECT_THROW(a.addRow(800, 1.0f), std::invalid_argument);  // not in the table
}

// The factored model's forests, all on one table, predict as forests of their own fed the same
// instances (the model's documented inputs, seeds and rules).
TEST(SharedInputs, FactoredModelEqualsForestsOfTheirOwn) {
  FactoredModel::Config c;
  c.numActions = 3;
  c.featMin = {0, 0, 0};
  c.featMax = {3, 3, 3};
  c.episodic = true;
  const std::uint64_t seed = 17;
  FactoredModel model(c, seed);
  std::vector<RandomForest> features;
  for (std::uint64_t j = 0; j < 3; ++j) {
    features.emplace_back(c.forest, rl_common::Random::deriveSeed(seed, "feature", j));
  }
  RandomForest reward(c.forest, rl_common::Random::deriveSeed(seed, "reward", 0));
  RandomForest terminal(c.forest, rl_common::Random::deriveSeed(seed, "terminal", 0));

  rl_common::Random rng(2);
  for (int k = 0; k < 300; ++k) {
    rl_common::Experience e;
    e.s = sampleInput(rng, 3);
    e.action = rng.uniformInt(0, 2);
    e.next = e.s;
    const auto moved = static_cast<std::size_t>(e.action);
    e.next[moved] = std::fmod(e.s[moved] + 1.0f, 4.0f);
    e.terminal = e.next[0] == 3.0f && e.next[1] == 3.0f;
    e.reward = e.terminal ? 1.0f : -0.1f * static_cast<float>(rng.uniformInt(0, 1));
    model.update({e});
    std::vector<float> x = e.s;
    for (int a = 0; a < 3; ++a) x.push_back(a == e.action ? 1.0f : 0.0f);
    if (!e.terminal) {
      for (std::size_t j = 0; j < 3; ++j) features[j].addInstance(x, e.next[j] - e.s[j]);
    }
    reward.addInstance(x, e.reward);
    terminal.addInstance(x, e.terminal ? 1.0f : 0.0f);
  }
  const auto view = model.factoredView();
  int compared = 0;
  for (int s0 = 0; s0 < 4; ++s0) {
    for (int s1 = 0; s1 < 4; ++s1) {
      for (int s2 = 0; s2 < 4; ++s2) {
        const rl_common::State s{float(s0), float(s1), float(s2)};
        for (int a = 0; a < 3; ++a) {
          std::vector<float> x(s.begin(), s.end());
          for (int b = 0; b < 3; ++b) x.push_back(b == a ? 1.0f : 0.0f);
          for (std::size_t j = 0; j < 3; ++j) {
            ASSERT_EQ(view->featureDistribution(s, a, j), features[j].predict(x));
          }
          const rl_common::StateActionInfo info = view->query(s, a);
          ASSERT_EQ(info.reward, static_cast<float>(expectation(reward.predict(x))));
          double t = 0.0;
          for (const auto& [value, p] : terminal.predict(x)) {
            t += std::clamp(static_cast<double>(value), 0.0, 1.0) * p;
          }
          ASSERT_EQ(info.termProb, static_cast<float>(t));
          ++compared;
        }
      }
    }
  }
  EXPECT_EQ(compared, 192);
}

}  // namespace
}  // namespace rl_agent
