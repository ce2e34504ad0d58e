/**
 * EnergyRooms: the four-room gridworld (Sutton, Precup & Singh, Artificial Intelligence 1999)
 * with an energy level that must be recharged, as the original package's EnergyRooms (shared/
 * spec/ORIGINAL.md §8, with the HEAD recharge squares of §0.1; used in Hester & Stone,
 * "TEXPLORE", Machine Learning 2013).
 *
 * Same map, start room and goal (1, 10) as FourRooms. State [ns, ew, energy]. Energy starts at
 * 10. Each step, before the move: on a recharge square (7,3), (7,7), (3,3) or (3,7) the energy
 * is set to 10, elsewhere it drops by 1 (with probability 0.8 in stochastic mode), never below
 * 0. Reward 0 for the step that reaches the goal (the episode ends), else −2 if the energy is
 * at most 0.1, else −1. Stochastic mode: moves go as intended with probability 0.8 and to
 * either perpendicular side with 0.1.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"
#include "rl_env/env/gridworld.h"

namespace rl_env {

class EnergyRooms : public rl_common::Environment {
 public:
  enum Action { kNorth = 0, kSouth = 1, kEast = 2, kWest = 3 };
  static constexpr int kNumActions = 4;
  static constexpr int kGoalNs = 1;
  static constexpr int kGoalEw = 10;
  static constexpr int kFullEnergy = 10;
  static constexpr int kMaxEnergy = 20;  ///< declared maximum of the energy feature
  static constexpr double kMoveSuccess = 0.8;
  static constexpr double kDrainProbability = 0.8;  ///< stochastic mode

  /// The recharge squares (ns, ew).
  static const std::array<std::pair<int, int>, 4>& rechargeSquares();

  EnergyRooms(std::uint64_t seed, bool stochastic);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override { return ns_ == kGoalNs && ew_ == kGoalEw; }
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::string name() const override { return "EnergyRooms"; }
  bool isStochastic() const override { return stochastic_; }

  /// Sets [ns, ew, energy]: an open cell and an integer energy in [0, 20]. Throws
  /// std::invalid_argument otherwise.
  void setState(const rl_common::State& s);

 private:
  void updateObservation();

  rl_common::Random rng_;
  bool stochastic_;
  Gridworld grid_;
  int ns_ = 0;
  int ew_ = 0;
  int energy_ = kFullEnergy;
  rl_common::State obs_;
};

}  // namespace rl_env
