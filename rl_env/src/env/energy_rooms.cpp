#include "rl_env/env/energy_rooms.h"

#include <algorithm>
#include <stdexcept>

#include "env_detail.h"
#include "rl_env/env/four_rooms.h"

namespace rl_env {

const std::array<std::pair<int, int>, 4>& EnergyRooms::rechargeSquares() {
  // The HEAD list; the original listed (7,7) twice instead of (3,7).
  static const std::array<std::pair<int, int>, 4> kSquares = {{{7, 3}, {7, 7}, {3, 3}, {3, 7}}};
  return kSquares;
}

EnergyRooms::EnergyRooms(std::uint64_t seed, bool stochastic)
    : rng_(seed), stochastic_(stochastic), grid_(FourRooms::makeMap()) {
  reset();
}

void EnergyRooms::updateObservation() {
  obs_ = {static_cast<float>(ns_), static_cast<float>(ew_), static_cast<float>(energy_)};
}

void EnergyRooms::reset() {
  ns_ = rng_.uniformInt(6, 10);
  ew_ = rng_.uniformInt(0, 4);
  energy_ = kFullEnergy;
  updateObservation();
}

float EnergyRooms::apply(int action) {
  detail::checkAction(action, kNumActions, "EnergyRooms::apply()");
  if (terminal()) return 0.0f;
  const auto& squares = rechargeSquares();
  if (std::find(squares.begin(), squares.end(), std::make_pair(ns_, ew_)) != squares.end()) {
    energy_ = kFullEnergy;
  } else if (!stochastic_ || rng_.bernoulli(kDrainProbability)) {
    energy_ = std::max(0, energy_ - 1);
  }
  const Gridworld::Direction dir = detail::sampleMove(
      rng_, static_cast<Gridworld::Direction>(action), stochastic_, kMoveSuccess);
  const auto [ns, ew] = grid_.move(ns_, ew_, dir);
  ns_ = ns;
  ew_ = ew;
  updateObservation();
  if (terminal()) return 0.0f;
  return energy_ <= 0.1 ? -2.0f : -1.0f;
}

void EnergyRooms::setState(const rl_common::State& s) {
  const char* where = "EnergyRooms::setState()";
  detail::checkStateSize(s, 3, where);
  const int ns = detail::integerFeature(s, 0, 0, FourRooms::kSize - 1, where);
  const int ew = detail::integerFeature(s, 1, 0, FourRooms::kSize - 1, where);
  const int energy = detail::integerFeature(s, 2, 0, kMaxEnergy, where);
  if (!grid_.open(ns, ew)) {
    throw std::invalid_argument(std::string(where) + ": (" + std::to_string(ns) + ", " +
                                std::to_string(ew) + ") is inside a wall");
  }
  ns_ = ns;
  ew_ = ew;
  energy_ = energy;
  updateObservation();
}

void EnergyRooms::getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const {
  *min = {0.0f, 0.0f, 0.0f};
  *max = {FourRooms::kSize - 1.0f, FourRooms::kSize - 1.0f, static_cast<float>(kMaxEnergy)};
}

void EnergyRooms::getMinMaxReward(float* min, float* max) const {
  *min = -2.0f;
  *max = 0.0f;
}

}  // namespace rl_env
