/**
 * Taxi: Dietterich's taxi domain (T. G. Dietterich, "Hierarchical Reinforcement Learning with
 * the MAXQ Value Function Decomposition", JAIR 13, 2000), as the original package's Taxi
 * (shared/spec/ORIGINAL.md §8), including the stochastic "fickle passenger" variant.
 *
 * A 5×5 grid (ns = row counted from the south, ew = column from the west) with four landmarks
 * (ns, ew): 0 = (4,0), 1 = (0,3), 2 = (4,4), 3 = (0,0), and Dietterich's walls: between columns
 * 0|1 and 2|3 in rows 0–1, between columns 1|2 in rows 3–4. State: [ns, ew, passenger
 * (0–3 = at that landmark, 4 = in the taxi), destination (0–3)]. Actions: N, S, E, W, PICKUP,
 * PUTDOWN. Reward −1 per action, −10 for an illegal PICKUP or PUTDOWN, +20 for putting the
 * passenger down at the destination, which ends the episode. Stochastic mode: moves go as
 * intended with probability 0.8 and to either perpendicular side with 0.1, and on the first move
 * action after a pickup the passenger changes destination with probability 0.3 (to one of the
 * other three landmarks, uniformly). Start: uniform taxi cell, passenger at a uniform landmark,
 * destination a different uniform landmark. No seed experiences (the original disabled them).
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"
#include "rl_common/true_model.h"
#include "rl_env/env/gridworld.h"

namespace rl_env {

class Taxi : public rl_common::Environment, public rl_common::TrueModel {
 public:
  enum Action { kNorth = 0, kSouth = 1, kEast = 2, kWest = 3, kPickup = 4, kPutdown = 5 };
  enum Feature { kNs = 0, kEw = 1, kPassenger = 2, kDestination = 3 };
  static constexpr int kNumActions = 6;
  static constexpr int kSize = 5;
  static constexpr int kInTaxi = 4;  ///< passenger value while riding
  static constexpr float kStepReward = -1.0f;
  static constexpr float kIllegalReward = -10.0f;
  static constexpr float kDeliveryReward = 20.0f;
  static constexpr double kMoveSuccess = 0.8;
  static constexpr double kFickleProbability = 0.3;

  /// The landmarks (ns, ew), indexed as the passenger and destination features.
  static const std::array<std::pair<int, int>, 4>& landmarks();

  Taxi(std::uint64_t seed, bool stochastic);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0 (the protocol
  /// resets before acting again).
  float apply(int action) override;
  bool terminal() const override;
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::string name() const override { return "Taxi"; }
  bool isStochastic() const override { return stochastic_; }

  // rl_common::TrueModel
  /// Exact outcomes of the move noise and the pickup/putdown rules. The fickle passenger's
  /// destination change depends on hidden history (a pickup just happened), so it is not part
  /// of these distributions: they are what the environment does after setState(s), which
  /// clears that history. Terminal states are absorbing (self-loop, reward 0).
  std::vector<rl_common::Outcome> transitions(const rl_common::State& s, int action) const override;
  /// Every taxi cell with every (passenger, destination) of an unfinished episode, plus the
  /// four terminal states (passenger delivered, taxi on its landmark).
  std::vector<rl_common::State> reachableStates() const override;
  /// Sets the state and clears a pending destination change.
  void setState(const rl_common::State& s) override;

  /// The walls.
  const Gridworld& grid() const { return grid_; }

 private:
  struct Pose {
    int ns, ew, passenger, destination;
  };
  static bool isTerminal(const Pose& p) { return p.passenger == p.destination; }
  Pose decode(const rl_common::State& s, const char* where) const;
  /// Applies an effective action without noise; sets *pickedUp on a successful pickup.
  float applyEffect(Pose* p, int effect, bool* pickedUp) const;
  static rl_common::State observe(const Pose& p);

  rl_common::Random rng_;
  bool stochastic_;
  Gridworld grid_;
  Pose pose_{};
  bool ficklePending_ = false;  ///< a pickup happened and no move has followed yet
  rl_common::State obs_;
};

}  // namespace rl_env
