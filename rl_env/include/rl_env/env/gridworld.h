/**
 * Gridworld: wall occupancy of a rectangular grid, shared by the grid environments (taxi,
 * tworooms, fourrooms, energy). Not an Environment itself, as in the original package.
 *
 * Cells are (ns, ew) with ns the row counted from the south (NORTH is ns + 1) and ew the
 * column counted from the west (EAST is ew + 1). A move is blocked by the grid's edge, by a thin
 * wall between two cells, or by a solid (blocked) cell. Directions use the original's numbering
 * 0 = N, 1 = S, 2 = E, 3 = W, which is also the action numbering of the grid environments.
 */
#pragma once

#include <utility>
#include <vector>

namespace rl_env {

class Gridworld {
 public:
  enum Direction { kNorth = 0, kSouth = 1, kEast = 2, kWest = 3 };

  /// An open grid of `height` rows (ns) and `width` columns (ew). Throws
  /// std::invalid_argument unless both are positive.
  Gridworld(int height, int width);

  int height() const { return height_; }
  int width() const { return width_; }

  /// True if (ns, ew) lies on the grid.
  bool inside(int ns, int ew) const;
  /// True if (ns, ew) is on the grid and not a solid cell.
  bool open(int ns, int ew) const;
  /// Every open cell as an (ns, ew) state, row by row: the reachable states of a plain grid.
  std::vector<std::vector<float>> openCells() const;

  /// Adds a thin wall on side `dir` of cell (ns, ew) (and so on the opposite side of the
  /// neighbour). Throws std::out_of_range if the cell is off the grid.
  void addWall(int ns, int ew, Direction dir);
  /// Makes (ns, ew) a solid cell that no move can enter. Throws std::out_of_range if off grid.
  void block(int ns, int ew);

  /// True if moving from (ns, ew) in direction `dir` is blocked (grid edge, thin wall or solid
  /// target), as the original's wall(ns, ew, dir).
  bool wall(int ns, int ew, Direction dir) const;
  /// The cell reached by moving from (ns, ew) in direction `dir`: the neighbour, or (ns, ew)
  /// itself if the move is blocked.
  std::pair<int, int> move(int ns, int ew, Direction dir) const;

  /// The two directions perpendicular to `dir` (E, W for N/S; N, S for E/W).
  static std::pair<Direction, Direction> perpendicular(Direction dir);
  /// The row and column change of one step in direction `dir`.
  static std::pair<int, int> delta(Direction dir);

 private:
  int index(int ns, int ew) const { return ns * width_ + ew; }

  int height_;
  int width_;
  std::vector<bool> solid_;
  std::vector<bool> wallNorth_;  ///< wall between (ns, ew) and (ns + 1, ew)
  std::vector<bool> wallEast_;   ///< wall between (ns, ew) and (ns, ew + 1)
};

}  // namespace rl_env
