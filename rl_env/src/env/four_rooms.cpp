#include "rl_env/env/four_rooms.h"

#include <stdexcept>

#include "env_detail.h"

namespace rl_env {

Gridworld FourRooms::makeMap() {
  Gridworld g(kSize, kSize);
  for (int ns = 0; ns < kSize; ++ns) {
    if (ns != 8 && ns != 1) g.block(ns, 5);  // north-south wall, hallways at ns 8 and 1
  }
  for (int ew = 0; ew < 5; ++ew) {
    if (ew != 1) g.block(5, ew);  // west rooms' dividing wall, hallway at ew 1
  }
  for (int ew = 6; ew < kSize; ++ew) {
    if (ew != 8) g.block(4, ew);  // east rooms' dividing wall, hallway at ew 8
  }
  return g;
}

FourRooms::FourRooms(std::uint64_t seed, bool stochastic)
    : rng_(seed), stochastic_(stochastic), grid_(makeMap()) {
  reset();
}

void FourRooms::reset() {
  ns_ = rng_.uniformInt(6, 10);
  ew_ = rng_.uniformInt(0, 4);
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_)};
}

float FourRooms::apply(int action) {
  detail::checkAction(action, kNumActions, "FourRooms::apply()");
  if (terminal()) return 0.0f;
  const Gridworld::Direction dir = detail::sampleMove(
      rng_, static_cast<Gridworld::Direction>(action), stochastic_, kMoveSuccess);
  const auto [ns, ew] = grid_.move(ns_, ew_, dir);
  ns_ = ns;
  ew_ = ew;
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_)};
  return terminal() ? 0.0f : -1.0f;
}

std::pair<int, int> FourRooms::decode(const rl_common::State& s, const char* where) const {
  detail::checkStateSize(s, 2, where);
  const int ns = detail::integerFeature(s, 0, 0, kSize - 1, where);
  const int ew = detail::integerFeature(s, 1, 0, kSize - 1, where);
  if (!grid_.open(ns, ew)) {
    throw std::invalid_argument(std::string(where) + ": (" + std::to_string(ns) + ", " +
                                std::to_string(ew) + ") is inside a wall");
  }
  return {ns, ew};
}

std::vector<rl_common::Outcome> FourRooms::transitions(const rl_common::State& s,
                                                       int action) const {
  detail::checkAction(action, kNumActions, "FourRooms::transitions()");
  const auto [ns, ew] = decode(s, "FourRooms::transitions()");
  std::vector<rl_common::Outcome> out;
  if (ns == kGoalNs && ew == kGoalEw) {
    detail::addOutcome(&out, s, 0.0f, true, 1.0);
    return out;
  }
  for (const auto& [dir, p] : detail::moveDistribution(static_cast<Gridworld::Direction>(action),
                                                       stochastic_, kMoveSuccess)) {
    const auto [toNs, toEw] = grid_.move(ns, ew, dir);
    const bool goal = toNs == kGoalNs && toEw == kGoalEw;
    detail::addOutcome(&out, {static_cast<float>(toNs), static_cast<float>(toEw)},
                       goal ? 0.0f : -1.0f, goal, p);
  }
  return out;
}

std::vector<rl_common::State> FourRooms::reachableStates() const { return grid_.openCells(); }

void FourRooms::setState(const rl_common::State& s) {
  const auto [ns, ew] = decode(s, "FourRooms::setState()");
  ns_ = ns;
  ew_ = ew;
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_)};
}

void FourRooms::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f};
  *max = {kSize - 1.0f, kSize - 1.0f};
}

void FourRooms::getMinMaxReward(float* min, float* max) const {
  *min = -1.0f;
  *max = 0.0f;
}

}  // namespace rl_env
