#include "rl_agent/model/m5_tree.h"

#include <gtest/gtest.h>

#include <cmath>

#include "rl_agent/model/m5_model.h"
#include "rl_common/random.h"

using rl_agent::M5Tree;

namespace {
// Piecewise linear in x0, independent of x1: x0 + 1 up to 0.5, 4 − 2 x0 above (a jump of 1.5
// at 0.5 and two slopes).
double piecewise(double x0) { return x0 <= 0.5 ? x0 + 1.0 : 4.0 - 2.0 * x0; }
}  // namespace

TEST(M5Tree, FitsALinearFunctionWithOneLeaf) {
  M5Tree tree(2, M5Tree::Config{});
  rl_common::Random rng(1);
  std::vector<std::vector<float>> X;
  std::vector<double> y;
  for (int i = 0; i < 100; ++i) {
    const float a = float(rng.uniform()), b = float(rng.uniform());
    X.push_back({a, b});
    y.push_back(3.0 * a - 2.0 * b + 1.0);
  }
  tree.fit(X, y);
  EXPECT_EQ(tree.numLeaves(), 1u);  // pruned back to the root's linear model
  EXPECT_NEAR(tree.predict({0.25f, 0.75f}), 3 * 0.25 - 2 * 0.75 + 1, 1e-4);
  EXPECT_NEAR(tree.predict({2.0f, -1.0f}), 9.0, 1e-3);  // linear models extrapolate
}

TEST(M5Tree, FitsAKnownPiecewiseLinearFunction) {
  M5Tree tree(2, M5Tree::Config{});
  rl_common::Random rng(2);
  std::vector<std::vector<float>> X;
  std::vector<double> y;
  for (int i = 0; i < 300; ++i) {
    const float a = float(rng.uniform()), b = float(rng.uniform());
    X.push_back({a, b});
    y.push_back(piecewise(a));
  }
  tree.fit(X, y);
  EXPECT_LE(tree.numLeaves(), 4u);  // two pieces (a few leaves near the break at most)
  double worst = 0.0;
  for (double a = 0.0; a <= 1.0; a += 0.01) {
    if (std::fabs(a - 0.5) < 0.02) continue;
    worst = std::max(worst, std::fabs(tree.predict({float(a), 0.3f}) - piecewise(a)));
  }
  EXPECT_LT(worst, 1e-3);
  const auto* root = tree.snapshot().root();
  ASSERT_NE(root, nullptr);
  EXPECT_EQ(root->feature, 0);  // the split is on x0, near 0.5
  EXPECT_NEAR(root->threshold, 0.5, 0.02);
}

TEST(M5Tree, LearnsOnlineAndRebuildsOnlyOnError) {
  M5Tree tree(1, M5Tree::Config{});
  EXPECT_DOUBLE_EQ(tree.predict({0.3f}), 0.0);  // no data
  EXPECT_TRUE(tree.add({0.0f}, 1.0));
  EXPECT_TRUE(tree.add({1.0f}, 2.0));   // predicted 1: rebuilt (a constant 1.5: too few to split)
  EXPECT_FALSE(tree.add({0.5f}, 1.5));  // already predicted: no rebuild
  EXPECT_TRUE(tree.add({2.0f}, 3.0));
  EXPECT_EQ(tree.numExamples(), 4u);
  EXPECT_THROW(tree.add({0.0f, 1.0f}, 1.0), std::invalid_argument);
  EXPECT_THROW(tree.add({0.0f}, NAN), std::invalid_argument);
}

TEST(M5Model, PredictsContinuousDynamics) {
  // s' = s + 0.1 (action 0) or s − 0.1 (action 1), clipped to [0, 1]; reward = s.
  rl_agent::M5Model::Config c;
  c.numActions = 2;
  c.featMin = {0.0f};
  c.featMax = {1.0f};
  c.episodic = false;
  rl_agent::M5Model model(c);
  auto before = model.view()->query({0.5f}, 0);
  EXPECT_FALSE(before.known);
  rl_common::Random rng(3);
  std::vector<rl_common::Experience> batch;
  for (int i = 0; i < 60; ++i) {
    const float s = float(rng.uniform(0.1, 0.9));
    const int a = i % 2;
    batch.push_back({{s}, a, s, {a == 0 ? s + 0.1f : s - 0.1f}, false});
  }
  model.update(batch);
  const auto info = model.view()->query({0.42f}, 1);
  ASSERT_EQ(info.transitions.size(), 1u);
  EXPECT_NEAR(info.transitions[0].first[0], 0.32f, 1e-3);
  EXPECT_NEAR(info.reward, 0.42f, 1e-3);
  EXPECT_FLOAT_EQ(model.view()->query({0.95f}, 0).transitions[0].first[0], 1.0f);  // clipped
}
