#include "rl_env/env/gridworld.h"

#include <stdexcept>
#include <string>

namespace rl_env {

Gridworld::Gridworld(int height, int width) : height_(height), width_(width) {
  if (height <= 0 || width <= 0) {
    throw std::invalid_argument("Gridworld::Gridworld(): size must be positive, got " +
                                std::to_string(height) + "x" + std::to_string(width));
  }
  const std::size_t n = static_cast<std::size_t>(height) * static_cast<std::size_t>(width);
  solid_.assign(n, false);
  wallNorth_.assign(n, false);
  wallEast_.assign(n, false);
}

bool Gridworld::inside(int ns, int ew) const {
  return ns >= 0 && ns < height_ && ew >= 0 && ew < width_;
}

bool Gridworld::open(int ns, int ew) const { return inside(ns, ew) && !solid_[index(ns, ew)]; }

void Gridworld::addWall(int ns, int ew, Direction dir) {
  if (!inside(ns, ew)) {
    throw std::out_of_range("Gridworld::addWall(): cell (" + std::to_string(ns) + ", " +
                            std::to_string(ew) + ") is off the grid");
  }
  switch (dir) {
    case kNorth:
      wallNorth_[index(ns, ew)] = true;
      break;
    case kSouth:
      if (ns > 0) wallNorth_[index(ns - 1, ew)] = true;
      break;
    case kEast:
      wallEast_[index(ns, ew)] = true;
      break;
    case kWest:
      if (ew > 0) wallEast_[index(ns, ew - 1)] = true;
      break;
  }
}

void Gridworld::block(int ns, int ew) {
  if (!inside(ns, ew)) {
    throw std::out_of_range("Gridworld::block(): cell (" + std::to_string(ns) + ", " +
                            std::to_string(ew) + ") is off the grid");
  }
  solid_[index(ns, ew)] = true;
}

bool Gridworld::wall(int ns, int ew, Direction dir) const {
  const auto [dns, dew] = delta(dir);
  const int tns = ns + dns;
  const int tew = ew + dew;
  if (!open(tns, tew)) return true;
  switch (dir) {
    case kNorth:
      return wallNorth_[index(ns, ew)];
    case kSouth:
      return wallNorth_[index(tns, tew)];
    case kEast:
      return wallEast_[index(ns, ew)];
    case kWest:
      return wallEast_[index(tns, tew)];
  }
  return true;
}

std::pair<int, int> Gridworld::move(int ns, int ew, Direction dir) const {
  if (wall(ns, ew, dir)) return {ns, ew};
  const auto [dns, dew] = delta(dir);
  return {ns + dns, ew + dew};
}

std::pair<Gridworld::Direction, Gridworld::Direction> Gridworld::perpendicular(Direction dir) {
  if (dir == kNorth || dir == kSouth) return {kEast, kWest};
  return {kNorth, kSouth};
}

std::pair<int, int> Gridworld::delta(Direction dir) {
  switch (dir) {
    case kNorth:
      return {1, 0};
    case kSouth:
      return {-1, 0};
    case kEast:
      return {0, 1};
    case kWest:
      return {0, -1};
  }
  return {0, 0};
}

std::vector<std::vector<float>> Gridworld::openCells() const {
  std::vector<std::vector<float>> out;
  for (int ns = 0; ns < height_; ++ns) {
    for (int ew = 0; ew < width_; ++ew) {
      if (open(ns, ew)) out.push_back({static_cast<float>(ns), static_cast<float>(ew)});
    }
  }
  return out;
}

}  // namespace rl_env
