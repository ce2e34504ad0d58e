/**
 * FuelRooms ("fuelworld"): navigation to a goal with a fuel tank refilled at stations of varying
 * cost, as the original package's FuelRooms (shared/spec/ORIGINAL.md §8; Hester & Stone,
 * "Generalized model learning for reinforcement learning in factored domains", AAMAS 2009, and
 * "TEXPLORE", Machine Learning 2013).
 *
 * An open 21×31 grid (ns 0–20 from the south, ew 0–30 from the west); moves that would leave
 * the grid stop at its edge, each coordinate separately. State [ns, ew, energy]. Actions N, NE,
 * E, SE, S, SW, W, NW; stochastic mode: the intended move with probability 0.8, each
 * neighbouring (±45°) move with 0.1. Each step costs 1 energy; ending the step on a fuel row
 * (ns 0 or 20) adds 20, up to 60. Reward: −400 if the energy falls below 0 (the episode ends),
 * 0 on reaching the goal (11, 24) (the episode ends), on a fuel row −10 (row 20) or −13 (row 0)
 * minus 8 + (ew mod 5) (or minus 5·(ew mod 5) with --highvar), else −1 for a cardinal move and
 * −1.4 for a diagonal one (the move actually taken). Start: ns 7–12, ew 0–4, energy 14–18,
 * uniformly. Four seed experiences with random positions from the seed's own stream: reaching
 * the goal, fuelling on row 20, fuelling on row 0, and running out of fuel.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_env {

class FuelRooms : public rl_common::Environment {
 public:
  enum Action {
    kNorth = 0,
    kNorthEast = 1,
    kEast = 2,
    kSouthEast = 3,
    kSouth = 4,
    kSouthWest = 5,
    kWest = 6,
    kNorthWest = 7
  };
  static constexpr int kNumActions = 8;
  static constexpr int kHeight = 21;
  static constexpr int kWidth = 31;
  static constexpr int kGoalNs = 11;
  static constexpr int kGoalEw = 24;
  static constexpr int kMaxEnergy = 60;
  static constexpr int kFuelGain = 20;
  static constexpr float kOutOfFuelReward = -400.0f;
  static constexpr double kMoveSuccess = 0.8;

  FuelRooms(std::uint64_t seed, bool stochastic, bool highVariance);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override;
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::vector<rl_common::Experience> seedExperiences() const override { return seeds_; }
  std::string name() const override { return "FuelRooms"; }
  bool isStochastic() const override { return stochastic_; }

  /// Sets [ns, ew, energy]: a cell of the grid and an integer energy in [-1, 60]. Throws
  /// std::invalid_argument otherwise.
  void setState(const rl_common::State& s);
  /// The reward of a step ending on fuel row (ns, ew), ns 0 or 20.
  float fuelCost(int ns, int ew) const;

 private:
  struct Pose {
    int ns, ew, energy;
  };
  /// The deterministic step: applies the move actually taken; returns the reward.
  float step(Pose* p, int move) const;
  static bool isTerminal(const Pose& p);
  static rl_common::State observe(const Pose& p);
  rl_common::Experience seed(Pose from, int move) const;
  void makeSeeds();

  rl_common::Random rng_;
  bool stochastic_;
  bool highVariance_;
  Pose pose_{};
  rl_common::State obs_;
  std::vector<rl_common::Experience> seeds_;
};

}  // namespace rl_env
