/**
 * CartPole: balancing a pole on a cart (Barto, Sutton & Anderson, "Neuronlike adaptive elements
 * that can solve difficult learning control problems", IEEE SMC 13, 1983), as the original
 * package's CartPole (shared/spec/ORIGINAL.md §8).
 *
 * The standard published dynamics (Barto et al. 1983, as in Sutton's reference cart-pole code):
 * g = 9.8 m/s², cart 1.0 kg, pole 0.1 kg, pole half-length 0.5 m, force ±10 N, Euler steps of
 * τ = 0.02 s. State [x, ẋ, θ, θ̇] declared in [±2.5 m, ±3 m/s, ±12° (in radians), ±π rad/s];
 * actions 0 = push left, 1 = push right. Reward +1 per step, and 0 for the step on which the
 * pole passes 12° or the cart passes 2.4 m, which ends the episode. Agents see the state
 * clipped to the declared ranges (a failing step can overshoot them); the failure test uses the
 * true state. Stochastic mode: the force gets 10·U(−0.5, 0.5) noise and each feature starts
 * uniform in [−0.05, 0.05); deterministic mode starts at 0. Four seed experiences: the pole
 * falling either way and the cart leaving either side.
 */
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rl_common/environment.h"
#include "rl_common/random.h"

namespace rl_env {

class CartPole : public rl_common::Environment {
 public:
  enum Action { kLeft = 0, kRight = 1 };
  static constexpr int kNumActions = 2;
  static constexpr double kForce = 10.0;
  static constexpr double kTau = 0.02;
  static constexpr double kFailAngle = 12.0 * 3.14159265358979323846 / 180.0;
  static constexpr double kFailPosition = 2.4;

  /// The physical state [x, ẋ, θ, θ̇].
  using Physics = std::array<double, 4>;

  CartPole(std::uint64_t seed, bool stochastic);

  // rl_common::Environment
  const rl_common::State& sensation() const override { return obs_; }
  /// Applies an action. In a terminal state nothing changes and the reward is 0.
  float apply(int action) override;
  bool terminal() const override { return failed(physics_); }
  void reset() override;
  int numActions() const override { return kNumActions; }
  void getMinMaxFeatures(std::vector<float>* min, std::vector<float>* max) const override;
  void getMinMaxReward(float* min, float* max) const override;
  std::vector<rl_common::Experience> seedExperiences() const override;
  std::string name() const override { return "CartPole"; }
  bool isStochastic() const override { return stochastic_; }

  /// Sets the physical state [x, ẋ, θ, θ̇]. Throws std::invalid_argument unless it has 4
  /// finite values.
  void setState(const rl_common::State& s);
  /// The unclipped physical state.
  const Physics& physics() const { return physics_; }

  /// One Euler step of the dynamics under `force` (N).
  static Physics step(const Physics& p, double force);
  /// True if the pole passed 12° or the cart passed 2.4 m.
  static bool failed(const Physics& p);
  /// The state agents see: `p` clipped to the declared ranges.
  static rl_common::State observe(const Physics& p);

 private:
  rl_common::Random rng_;
  bool stochastic_;
  Physics physics_{};
  rl_common::State obs_;
};

}  // namespace rl_env
