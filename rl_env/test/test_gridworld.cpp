// Gridworld: edges, thin walls on both sides, solid cells, moves, directions.
#include "rl_env/env/gridworld.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <utility>

namespace {

using rl_env::Gridworld;

TEST(Gridworld, EdgesBlock) {
  const Gridworld g(3, 4);
  EXPECT_TRUE(g.wall(2, 1, Gridworld::kNorth));
  EXPECT_TRUE(g.wall(0, 1, Gridworld::kSouth));
  EXPECT_TRUE(g.wall(1, 3, Gridworld::kEast));
  EXPECT_TRUE(g.wall(1, 0, Gridworld::kWest));
  EXPECT_FALSE(g.wall(1, 1, Gridworld::kNorth));
  EXPECT_EQ(g.move(1, 1, Gridworld::kNorth), std::make_pair(2, 1));
  EXPECT_EQ(g.move(1, 1, Gridworld::kEast), std::make_pair(1, 2));
  EXPECT_EQ(g.move(2, 1, Gridworld::kNorth), std::make_pair(2, 1));
}

TEST(Gridworld, ThinWallsBlockBothWays) {
  Gridworld g(3, 3);
  g.addWall(1, 1, Gridworld::kEast);
  EXPECT_TRUE(g.wall(1, 1, Gridworld::kEast));
  EXPECT_TRUE(g.wall(1, 2, Gridworld::kWest));
  g.addWall(1, 1, Gridworld::kSouth);
  EXPECT_TRUE(g.wall(0, 1, Gridworld::kNorth));
  EXPECT_FALSE(g.wall(1, 1, Gridworld::kNorth));
  EXPECT_THROW(g.addWall(3, 0, Gridworld::kEast), std::out_of_range);
}

TEST(Gridworld, SolidCellsCannotBeEntered) {
  Gridworld g(3, 3);
  g.block(1, 1);
  EXPECT_FALSE(g.open(1, 1));
  EXPECT_TRUE(g.open(0, 0));
  EXPECT_FALSE(g.open(-1, 0));
  EXPECT_TRUE(g.wall(0, 1, Gridworld::kNorth));
  EXPECT_TRUE(g.wall(2, 1, Gridworld::kSouth));
  EXPECT_TRUE(g.wall(1, 0, Gridworld::kEast));
  EXPECT_TRUE(g.wall(1, 2, Gridworld::kWest));
  EXPECT_THROW(g.block(0, 3), std::out_of_range);
}

TEST(Gridworld, Directions) {
  EXPECT_EQ(Gridworld::perpendicular(Gridworld::kNorth),
            std::make_pair(Gridworld::kEast, Gridworld::kWest));
  EXPECT_EQ(Gridworld::perpendicular(Gridworld::kWest),
            std::make_pair(Gridworld::kNorth, Gridworld::kSouth));
  EXPECT_EQ(Gridworld::delta(Gridworld::kSouth), std::make_pair(-1, 0));
  EXPECT_THROW(Gridworld(0, 3), std::invalid_argument);
}

}  // namespace
