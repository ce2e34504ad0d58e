/**
 * FourRooms: the four-room gridworld of Sutton, Precup & Singh, "Between MDPs and semi-MDPs: A
 * framework for temporal abstraction in reinforcement learning", Artificial Intelligence 112,
 * 1999, as the original package's FourRooms with its 4-argument constructor (shared/spec/
 * ORIGINAL.md §8: negative rewards, no extra features).
 *
 * The 11×11 interior of Sutton et al.'s map (ns = row from the south, ew = column from the west),
 * 104 open cells: a wall column ew = 5 with hallways at ns = 8 and ns = 1, a wall row ns = 5 on
 * the west side with a hallway at ew = 1, and a wall row ns = 4 on the east side with a hallway
 * at ew = 8. State [ns, ew]; actions N, S, E, W. Reward −1 per step and 0 for the step that
 * reaches the goal (1, 10) in the south-east room, which ends the episode. Stochastic mode:
 * moves go as intended with probability 0.8 and to either perpendicular side with 0.1. Start: a
 * uniform cell of the north-west room (ns 6–10, ew 0–4).
 */
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"
#include "rl_env/env/gridworld.h"

namespace rl_env {

class FourRooms : public rl_common::Environment, public rl_common::TrueModel {
 public:
  enum Action { kNorth = 0, kSouth = 1, kEast = 2, kWest = 3 };
  static constexpr int kNumActions = 4;
  static constexpr int kSize = 11;
  static constexpr int kGoalNs = 1;
  static constexpr int kGoalEw = 10;
  static constexpr double kMoveSuccess = 0.8;

  /// Sutton et al.'s four-room map (also used by EnergyRooms).
  static Gridworld makeMap();

  FourRooms(std::uint64_t seed, bool stochastic);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override { return ns_ == kGoalNs && ew_ == kGoalEw; }
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::string name() const override { return "FourRooms"; }
  bool isStochastic() const override { return stochastic_; }

  // rl_common::TrueModel
  /// Exact outcomes of the move noise; the goal is absorbing (self-loop, reward 0).
  std::vector<rl_common::Outcome> transitions(const rl_common::State& s, int action) const override;
  /// Every open cell (104), the goal included.
  std::vector<rl_common::State> reachableStates() const override;
  void setState(const rl_common::State& s) override;

  const Gridworld& grid() const { return grid_; }

 private:
  std::pair<int, int> decode(const rl_common::State& s, const char* where) const;

  rl_common::Random rng_;
  bool stochastic_;
  Gridworld grid_;
  int ns_ = 0;
  int ew_ = 0;
  rl_common::State obs_;
};

}  // namespace rl_env
