/**
 * MountainCar ("mcar"): an under-powered car must drive out of a valley (Moore, "Efficient
 * memory-based learning for robot control", PhD thesis, 1990; the formulation of Sutton & Barto,
 * "Reinforcement Learning: An Introduction", 1998), as the original package's MountainCar with
 * the HEAD behaviour of shared/spec/ORIGINAL.md §0.1.
 *
 * State [position in [−1.2, 0.6], velocity in [−0.07, 0.07]]; actions 0, 1, 2 push with force
 * a − 1. Each step: v += 0.001·force − 0.0025·cos(3·position), clipped to ±0.07; position += v
 * (the new velocity, the HEAD fix), clipped to [−1.2, 0.6], and the velocity is zeroed on hitting
 * the left end (Sutton & Barto). Reward −1 per step and 0 for the step that reaches position
 * 0.6, which ends the episode. Stochastic mode: the force gets U(−0.5, 0.5) noise and the start
 * is uniform (position in [−1.2, 0.59), velocity in [−0.07, 0.07)); deterministic mode starts
 * at (0, 0) (HEAD). With delay k > 0 the agent observes the state of k steps ago. Four seed
 * experiences (undelayed only): three steps into the goal and one against the left end.
 */
#pragma once

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_env {

class MountainCar : public rl_common::Environment {
 public:
  static constexpr int kNumActions = 3;
  static constexpr double kMinPosition = -1.2;
  static constexpr double kMaxPosition = 0.6;
  static constexpr double kMaxVelocity = 0.07;
  static constexpr double kGoalPosition = 0.6;

  /// `delay` >= 0 steps of observation delay; throws std::invalid_argument if negative.
  MountainCar(std::uint64_t seed, bool stochastic, int delay);

  // rl_common::Environment
  /// The observed state (the true state of `delay` steps ago).
  const rl_common::State& sensation() const override { return history_.front(); }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override { return position_ >= kGoalPosition; }
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::vector<rl_common::Experience> seedExperiences() const override;
  std::string name() const override { return "MountainCar"; }
  bool isStochastic() const override { return stochastic_; }

  /// Sets the true [position, velocity] (and the whole observation history to it). Throws
  /// std::invalid_argument outside the declared ranges.
  void setState(const rl_common::State& s);
  /// The true (undelayed) state.
  rl_common::State trueState() const;
  int delay() const { return delay_; }

  /// One noise-free step of the dynamics with force `force`; returns the reward.
  static float step(double* position, double* velocity, double force);

 private:
  rl_common::Random rng_;
  bool stochastic_;
  int delay_;
  double position_ = 0.0;
  double velocity_ = 0.0;
  std::deque<rl_common::State> history_;  ///< the last delay + 1 true states, oldest first
};

}  // namespace rl_env
