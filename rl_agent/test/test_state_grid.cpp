// StateGrid: the original's binning, written once for agents and planners.
#include "rl_agent/planner/state_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

using rl_agent::StateGrid;

TEST(StateGrid, RoundsToTheNearestMultipleOfTheWidthAnchoredAtZero) {
  const StateGrid g({4, 0}, {0.0f, 0.0f}, {7.0f, 10.0f});  // widths 1.75 and none
  ASSERT_TRUE(g.bins());
  EXPECT_FLOAT_EQ(g.width(0), 1.75f);
  EXPECT_FLOAT_EQ(g.width(1), 0.0f);
  EXPECT_FLOAT_EQ(g.bin(0, 0.8f), 0.0f);
  EXPECT_FLOAT_EQ(g.bin(0, 0.9f), 1.75f);
  EXPECT_FLOAT_EQ(g.bin(0, 6.0f), 5.25f);
  EXPECT_FLOAT_EQ(g.bin(0, 6.2f), 7.0f);
  EXPECT_FLOAT_EQ(g.bin(0, -0.9f), -1.75f);     // half away from zero on both sides
  EXPECT_FALSE(std::signbit(g.bin(0, -0.1f)));  // -0 comes out as +0
  EXPECT_FLOAT_EQ(g.bin(1, 3.3f), 3.3f);        // 0 bins: continuous
  // Features beyond the grid (e.g. an action history) pass through.
  EXPECT_EQ(g.apply({0.9f, 3.3f, 1.0f}), (rl_common::State{1.75f, 3.3f, 1.0f}));
  EXPECT_TRUE(std::isfinite(g.bin(0, 1e30f)));  // no int overflow for huge values
}

TEST(StateGrid, OneCountForEveryFeatureOrNone) {
  const StateGrid all({2}, {0.0f, -1.0f}, {4.0f, 1.0f});
  EXPECT_FLOAT_EQ(all.width(0), 2.0f);
  EXPECT_FLOAT_EQ(all.width(1), 1.0f);
  const StateGrid none;
  EXPECT_FALSE(none.bins());
  EXPECT_EQ(none.apply({0.3f}), (rl_common::State{0.3f}));
  EXPECT_FALSE(StateGrid({0}, {0.0f}, {1.0f}).bins());
  EXPECT_FALSE(StateGrid({5}, {2.0f}, {2.0f}).bins());  // a constant feature
  EXPECT_THROW(StateGrid({1, 2, 3}, {0.0f, 0.0f}, {1.0f, 1.0f}), std::invalid_argument);
  EXPECT_THROW(StateGrid({-1}, {0.0f}, {1.0f}), std::invalid_argument);
}
